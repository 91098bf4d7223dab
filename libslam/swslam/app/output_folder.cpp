#include <swslam/app/output_folder.h>

#include <swslam/common/atomic_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace swslam::app
{
namespace fs = std::filesystem;

namespace
{
/** The staging folder of replaceRun: a killed run may leave it. */
constexpr const char* kStaging = ".swslam-staging";

/** "a directory", "a FIFO"...: what is at a path that should be a file. */
std::string describeFileType(fs::file_type type)
{
  switch (type)
  {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::symlink: return "a symbolic link";
    case fs::file_type::socket: return "a socket";
    case fs::file_type::block:
    case fs::file_type::character: return "a device";
    default: return "not a regular file";
  }
}
}  // namespace

OutputFolder::OutputFolder(const std::string& dir) : dir_(dir)
{
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("output folder '" + dir + "': " + why);
  };
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) fail("cannot be created" + (ec ? ": " + ec.message() : std::string()));
  const std::string lock_path = (fs::path(dir) / kLockFile).string();
  // The lock must be a file of its own: a folder, FIFO or device there is named, not taken for
  // the folder's fault (O_NONBLOCK: a FIFO's open does not wait for a writer).
  const auto lockIsNoFile = [&](const fs::file_status& st) {
    fail(std::string("its lock file ") + kLockFile + " is " + describeFileType(st.type()) +
         ", not a file: remove it (" + lock_path + ")");
  };
  if (const auto st = fs::symlink_status(lock_path, ec); fs::exists(st) && !fs::is_regular_file(st)) lockIsNoFile(st);
  lock_fd_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (lock_fd_ < 0)
    fail(std::string("cannot be written: its lock file ") + kLockFile + ": " + std::strerror(errno));
  struct stat st{};
  if (::fstat(lock_fd_, &st) != 0 || !S_ISREG(st.st_mode))
  {
    ::close(lock_fd_);
    lock_fd_ = -1;
    lockIsNoFile(fs::status(lock_path, ec));
  }
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0)
  {
    std::ifstream in(lock_path);
    std::string pid;
    std::getline(in, pid);
    ::close(lock_fd_);
    lock_fd_ = -1;
    fail("another run is writing into it" + (pid.empty() ? std::string() : " (process " + pid + ")"));
  }
  // The holder's process id, for the message above (the lock itself is the flock).
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(lock_fd_, 0) != 0 || ::pwrite(lock_fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size()))
    fail(std::string("cannot be written: its lock file ") + kLockFile + ": " + std::strerror(errno));
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file() && common::isAtomicTemporary(entry.path().filename().string()) && fs::remove(entry.path(), ec))
      stale_removed_++;
  const fs::path staging = fs::path(dir) / kStaging;
  if (fs::exists(staging, ec))
  {
    const auto removed = fs::remove_all(staging, ec);
    if (removed != static_cast<std::uintmax_t>(-1) && removed > 0) stale_removed_ += removed - 1;  // its files, not itself
  }
}

OutputFolder::~OutputFolder()
{
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

void OutputFolder::clearPreviousRun(const std::vector<std::string>& names)
{
  if (cleared_) return;
  cleared_ = true;
  std::error_code ec;
  for (const auto& name : names) fs::remove(fs::path(dir_) / name, ec);
}

OutputFolder::Replaced OutputFolder::replaceRun(
    const std::vector<std::string>& names,
    const std::function<std::vector<map::OutputProblem>(const std::string& dir)>& write)
{
  const fs::path dir(dir_), staging = dir / kStaging, unfinished = dir / kUnfinished;
  std::error_code ec;
  fs::remove_all(staging, ec);
  if (ec || !fs::create_directory(staging, ec) || ec)
    throw std::runtime_error("output folder '" + dir_ + "': cannot make " + kStaging +
                             (ec ? ": " + ec.message() : std::string()));
  Replaced out;
  out.problems = write(staging.string());
  bool previous = false;
  for (const auto& name : names) previous = previous || fs::exists(dir / name, ec);
  if (!out.problems.empty() && previous)
  {
    // Keep the previous run's outputs; this run's go beside them, whole.
    fs::remove_all(unfinished, ec);
    fs::rename(staging, unfinished, ec);
    if (ec) throw std::runtime_error("output folder '" + dir_ + "': cannot move " + kStaging + " to " + kUnfinished + ": " + ec.message());
    out.kept_previous = true;
    return out;
  }
  cleared_ = true;
  for (const auto& name : names)
  {
    const fs::path staged = staging / name, target = dir / name;
    if (fs::exists(staged, ec))
    {
      fs::rename(staged, target, ec);
      if (ec) out.problems.push_back({name, "cannot move it into the folder: " + ec.message()});
    }
    else
      fs::remove(target, ec);  // the previous run's, which this run did not write
  }
  fs::remove_all(staging, ec);
  fs::remove_all(unfinished, ec);
  return out;
}

}  // namespace swslam::app
