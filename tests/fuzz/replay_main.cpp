// The replay of a harness without libFuzzer (ctest, every build): feeds the harness's
// LLVMFuzzerTestOneInput the empty input, then every file of the folders given, in name
// order. A broken promise aborts, an exception the function does not document escapes: either
// fails the test. Prints each file before it runs, so a failure names its input.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s FOLDER...  (replays every file of each folder)\n", argv[0]);
    return 2;
  }
  LLVMFuzzerTestOneInput(nullptr, 0);
  size_t replayed = 0;
  for (int a = 1; a < argc; ++a)
  {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(argv[a]))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty())
    {
      std::fprintf(stderr, "replay: no input in %s\n", argv[a]);
      return 1;
    }
    for (const auto& f : files)
    {
      std::printf("replay: %s\n", f.c_str());
      std::fflush(stdout);
      std::ifstream in(f, std::ios::binary);
      if (!in)
      {
        std::fprintf(stderr, "replay: cannot read %s\n", f.c_str());
        return 1;
      }
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  std::printf("replay: %zu inputs, no failure\n", replayed);
  return 0;
}
