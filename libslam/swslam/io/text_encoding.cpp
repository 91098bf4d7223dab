#include <swslam/io/text_encoding.h>

#include <cstddef>

namespace swslam::io
{
namespace
{
bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

const std::string kUtf32Le("\xFF\xFE\0\0", 4), kUtf32Be("\0\0\xFE\xFF", 4), kUtf16Le("\xFF\xFE", 2),
    kUtf16Be("\xFE\xFF", 2);
}  // namespace

std::string wideTextEncoding(const std::string& head)
{
  if (startsWith(head, kUtf32Le)) return "UTF-32LE";
  if (startsWith(head, kUtf32Be)) return "UTF-32BE";
  if (startsWith(head, kUtf16Le)) return "UTF-16LE";
  if (startsWith(head, kUtf16Be)) return "UTF-16BE";
  // Without a mark: ASCII text in UTF-16 has a NUL after (LE) or before (BE) each character.
  size_t nul[2] = {0, 0}, count[2] = {0, 0};
  for (size_t i = 0; i < head.size(); i++)
  {
    count[i % 2]++;
    nul[i % 2] += head[i] == '\0';
  }
  if (head.size() < 8) return "";
  auto most = [](size_t n, size_t of) { return 4 * n >= 3 * of; };
  auto few = [](size_t n, size_t of) { return 4 * n <= of; };
  if (most(nul[1], count[1]) && few(nul[0], count[0])) return "UTF-16LE";
  if (most(nul[0], count[0]) && few(nul[1], count[1])) return "UTF-16BE";
  return "";
}

std::string wideTextProblem(const std::string& head)
{
  const std::string encoding = wideTextEncoding(head);
  if (encoding.empty()) return "";
  const std::string bom = startsWith(head, kUtf32Le)   ? "FF FE 00 00"
                          : startsWith(head, kUtf32Be) ? "00 00 FE FF"
                          : startsWith(head, kUtf16Le) ? "FF FE"
                          : startsWith(head, kUtf16Be) ? "FE FF"
                                                       : "";
  const std::string family = encoding.substr(0, 6);  // UTF-16 or UTF-32
  return "is " + encoding + " text (" +
         (bom.empty() ? "a NUL byte beside every character" : "it starts with the byte order mark " + bom) +
         "), not the ASCII of a log: convert it first (iconv -f " + family + " -t UTF-8)";
}

}  // namespace swslam::io
