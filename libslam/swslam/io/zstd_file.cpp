#include <swslam/io/zstd_file.h>

#include <zstd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

namespace swslam::io
{
void decompressZstdFile(const std::string& from, const std::string& to, uint64_t max_bytes)
{
  const std::string name = "'" + from + "'";
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(from, ec);
  if (ec) throw std::runtime_error("cannot open " + name + ": " + ec.message());
  const uint64_t bound = std::min(max_bytes, size * 32768);
  std::unique_ptr<FILE, int (*)(FILE*)> in(std::fopen(from.c_str(), "rb"), std::fclose);
  if (!in) throw std::runtime_error("cannot open " + name + ": " + std::strerror(errno));
  std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(to.c_str(), "wb"), std::fclose);
  if (!out) throw std::runtime_error("cannot write '" + to + "': " + std::strerror(errno));
  std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> ctx(ZSTD_createDCtx(), ZSTD_freeDCtx);
  std::vector<char> in_buf(ZSTD_DStreamInSize()), out_buf(1 << 20);
  uint64_t written = 0;
  size_t hint = 1;  // 0 once a frame ended
  std::string problem;
  for (size_t n; problem.empty() && (n = std::fread(in_buf.data(), 1, in_buf.size(), in.get())) > 0;)
  {
    ZSTD_inBuffer input{in_buf.data(), n, 0};
    while (problem.empty() && input.pos < input.size)
    {
      ZSTD_outBuffer output{out_buf.data(), out_buf.size(), 0};
      hint = ZSTD_decompressStream(ctx.get(), &output, &input);
      if (ZSTD_isError(hint))
        problem = std::string("corrupt zstd data: ") + ZSTD_getErrorName(hint);
      else if ((written += output.pos) > bound)
        problem = "it decompresses to more than " + std::to_string(bound) + " bytes (at most " +
                  std::to_string(max_bytes) + ", and 32768 times its " + std::to_string(size) + ")";
      else if (std::fwrite(out_buf.data(), 1, output.pos, out.get()) != output.pos)
        problem = "cannot write '" + to + "': " + std::strerror(errno);
    }
  }
  if (problem.empty() && std::ferror(in.get())) problem = std::string("cannot read it: ") + std::strerror(errno);
  if (problem.empty() && hint != 0) problem = "its zstd data is cut short (a truncated file)";
  if (problem.empty() && std::fclose(out.release()) != 0) problem = "cannot write '" + to + "': " + std::strerror(errno);
  if (!problem.empty())
  {
    out.reset();
    std::filesystem::remove(to, ec);
    throw std::runtime_error(name + ": " + problem);
  }
}

}  // namespace swslam::io
