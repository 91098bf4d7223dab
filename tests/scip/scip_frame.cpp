#include "scip_frame.h"

#include "scip_encoding.h"

#include <stdexcept>

namespace swslam::scip
{
namespace
{
constexpr std::pair<Fault, const char*> kFaultNames[] = {
    {Fault::None, "none"},
    {Fault::BadChecksum, "bad-checksum"},
    {Fault::TruncatedLine, "truncated-line"},
    {Fault::WrongEcho, "wrong-echo"},
};

/** The line (with checksum, without LF) corrupted by `fault`. */
std::string corrupt(std::string line, Fault fault)
{
  if (fault == Fault::BadChecksum)
  {
    char& sum = line.back();
    sum = static_cast<char>(0x30 + ((sum - 0x30 + 1) & 0x3F));
  }
  else if (fault == Fault::TruncatedLine)
    line.resize(line.size() / 2);
  return line;
}

/** Whether `line` (without LF) ends with the right checksum; strips it (and the ';' of a
 * parameter line, then setting `info`) into `body`. */
bool checkLine(std::string_view line, std::string& body, bool& info)
{
  info = false;
  if (line.size() < 2)
  {
    body = std::string(line);
    return false;
  }
  const std::string_view summed = line.substr(0, line.size() - 1);
  const char sum = line.back();
  if (summed.back() == ';' && checksum(summed.substr(0, summed.size() - 1)) == sum)
  {
    body = std::string(summed.substr(0, summed.size() - 1));
    info = true;
    return true;
  }
  body = std::string(summed);
  return checksum(summed) == sum;
}
}  // namespace

const char* faultName(Fault f)
{
  for (const auto& [fault, name] : kFaultNames)
    if (fault == f) return name;
  return "?";
}

Fault parseFault(std::string_view name)
{
  std::string known;
  for (const auto& [fault, n] : kFaultNames)
  {
    if (name == n) return fault;
    known += std::string(known.empty() ? "" : ", ") + n;
  }
  throw std::invalid_argument("unknown SCIP fault '" + std::string(name) + "' (known: " + known +
                              ")");
}

std::string serialize(const Frame& f, Fault fault)
{
  std::string out = f.echo;
  if (fault == Fault::WrongEcho && !out.empty()) out.back() = out.back() == '0' ? '1' : '0';
  out += '\n';

  std::string status = dataLine(f.status);
  status.pop_back();  // the LF
  std::vector<std::string> lines;
  for (const auto& body : f.lines)
  {
    lines.push_back(f.info_lines ? infoLine(body) : dataLine(body));
    lines.back().pop_back();
  }
  std::string& target = lines.empty() ? status : lines.front();
  target = corrupt(target, fault);

  out += status + '\n';
  for (const auto& line : lines) out += line + '\n';
  out += '\n';
  return out;
}

std::optional<ParsedFrame> parseFrame(std::string_view bytes)
{
  ParsedFrame p;
  size_t pos = 0;
  for (size_t index = 0;; index++)
  {
    const size_t lf = bytes.find('\n', pos);
    if (lf == std::string_view::npos) return std::nullopt;
    const std::string_view line = bytes.substr(pos, lf - pos);
    pos = lf + 1;
    if (index == 0)
    {
      p.frame.echo = std::string(line);
      continue;
    }
    if (line.empty()) break;
    std::string body;
    bool info = false;
    const bool ok = checkLine(line, body, info);
    p.checksums_ok = p.checksums_ok && ok;
    if (index == 1)
      p.frame.status = body;
    else
    {
      p.frame.info_lines = p.frame.info_lines || info;
      p.frame.lines.push_back(body);
    }
  }
  p.bytes = pos;
  return p;
}

}  // namespace swslam::scip
