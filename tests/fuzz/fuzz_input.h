#pragma once
// Shared by the harnesses: the input as a file (the readers take paths), and the check that
// ends a run on a broken promise (libFuzzer records the input as a crash; the replay fails).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace swslam::fuzz
{
/** A folder of this process's own under $TMPDIR (or /tmp), removed at a normal exit. */
inline const std::string& scratchDir()
{
  struct Dir
  {
    std::string path;
    Dir()
    {
      const char* tmp = std::getenv("TMPDIR");
      std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/swslam-fuzz-XXXXXX";
      if (!mkdtemp(pattern.data())) throw std::runtime_error("fuzz: cannot create " + pattern);
      path = pattern;
    }
    ~Dir()
    {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir;
  return dir.path;
}

/** `name` in the scratch folder. */
inline std::string scratchPath(const std::string& name) { return scratchDir() + "/" + name; }

/** Writes the input into the scratch folder as `name`; returns its path. */
inline std::string writeInput(const uint8_t* data, size_t size, const std::string& name)
{
  const std::string path = scratchPath(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) throw std::runtime_error("fuzz: cannot write " + path);
  return path;
}

/** Whether `text` starts with `prefix`. */
inline bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace swslam::fuzz

/** A promise of the code under test that the input broke: print it and abort. */
#define SWSLAM_FUZZ_CHECK(cond, what)                                                        \
  do                                                                                         \
  {                                                                                          \
    if (!(cond))                                                                             \
    {                                                                                        \
      std::fprintf(stderr, "fuzz check failed at %s:%d: %s (%s)\n", __FILE__, __LINE__, #cond, \
                   std::string(what).c_str());                                               \
      std::abort();                                                                          \
    }                                                                                        \
  } while (false)
