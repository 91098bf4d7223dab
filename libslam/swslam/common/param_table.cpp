#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace swslam::common
{
bool Range::contains(double v) const
{
  if (std::isnan(v)) return false;
  if (std::isinf(v) && !((v < 0 && std::isinf(lo) && !lo_open) || (v > 0 && std::isinf(hi) && !hi_open)))
    return false;
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::describe() const
{
  const bool low = std::isfinite(lo) || !lo_open, high = std::isfinite(hi) || !hi_open;
  if (low && high)
    return std::string("in ") + (lo_open ? "(" : "[") + shortestText(lo) + ", " + shortestText(hi) +
           (hi_open ? ")" : "]");
  if (low) return std::string(lo_open ? "> " : ">= ") + shortestText(lo);
  if (high) return std::string(hi_open ? "< " : "<= ") + shortestText(hi);
  return "a finite number";
}

Range anyNumber() { return {}; }
Range atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, true}; }
Range above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, true}; }
Range between(double lo, double hi) { return {lo, hi, false, false}; }
Range aboveUpTo(double lo, double hi) { return {lo, hi, true, false}; }
Range strictlyBetween(double lo, double hi) { return {lo, hi, true, true}; }

namespace
{
/** "1e+06" as "1e6", "1e-06" as "1e-6". */
std::string tidyExponent(std::string s)
{
  const size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

/** The shortest text, fixed or scientific, whose value `accept` takes; fixed for numbers
 * from 1e-4 that it writes in at most 8 characters ("0.0005", not "5e-4"). */
template <class Accept>
std::string shortestAccepted(double v, Accept accept)
{
  char buf[64];
  std::string fixed, scientific;
  for (int decimals = 0; decimals <= 20 && fixed.empty() && std::abs(v) < 1e16; decimals++)
  {
    std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
    if (accept(std::strtod(buf, nullptr))) fixed = buf;
  }
  for (int precision = 1; precision <= 17 && scientific.empty(); precision++)
  {
    std::snprintf(buf, sizeof(buf), "%.*e", precision - 1, v);
    if (accept(std::strtod(buf, nullptr))) scientific = tidyExponent(buf);
  }
  if (fixed.empty()) return scientific;
  if (std::abs(v) >= 1e-4 && fixed.size() <= 8) return fixed;
  return scientific.size() < fixed.size() ? scientific : fixed;
}
}  // namespace

std::string shortestText(double v)
{
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return shortestAccepted(v, [v](double x) { return x == v; });
}

std::string degreesText(double radians)
{
  if (std::isinf(radians)) return radians < 0 ? "-inf" : "inf";
  // RAD2DEG does not invert DEG2RAD exactly: the degrees that give `radians` may lie a few
  // ulps from RAD2DEG(radians). The shortest text of any of those that does is the one.
  const auto accept = [radians](double d) { return detail::deg2rad(d) == radians; };
  std::string best;
  double below = mrpt::RAD2DEG(radians), above = below;
  for (int ulps = 0; ulps <= 4; ulps++)
  {
    for (const double degrees : {below, above})
    {
      const std::string text = shortestAccepted(degrees, accept);
      if (!text.empty() && (best.empty() || text.size() < best.size())) best = text;
    }
    below = std::nextafter(below, -INFINITY);
    above = std::nextafter(above, INFINITY);
  }
  return best.empty() ? shortestText(mrpt::RAD2DEG(radians)) : best;
}

namespace detail
{
std::string trimmed(const std::string& s) { return mrpt::system::trim(s); }

std::string joined(const std::vector<std::string>& v)
{
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

bool sameName(const std::string& a, const std::string& b) { return mrpt::system::strCmpI(a, b); }

double deg2rad(double d) { return mrpt::DEG2RAD(d); }

std::string parseNumber(const std::string& value, double& out)
{
  if (value.empty()) return "has no value";
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (*end != '\0' || std::isnan(v)) return "is not a number";
  out = v;
  return {};
}

std::string parseInteger(const std::string& value, long long& out)
{
  if (value.empty()) return "has no value";
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(value.c_str(), &end, 10);
  if (*end != '\0' || errno == ERANGE) return "is not an integer";
  out = v;
  return {};
}

std::string parseBoolean(const std::string& value, bool& out)
{
  if (value.empty()) return "has no value";
  const std::string v = mrpt::system::lowerCase(value);
  if (v == "true" || v == "yes" || v == "1")
    out = true;
  else if (v == "false" || v == "no" || v == "0")
    out = false;
  else
    return "is not a boolean (true or false)";
  return {};
}

void checkNoInlineComment(const std::string& section, const std::string& key, const std::string& value)
{
  // MRPT's reader keeps the rest of the line in the value: "true  # note" would read as
  // false, silently. Comments go on lines of their own.
  if (value.find(" #") != std::string::npos || value.find("\t#") != std::string::npos ||
      value.find(" ;") != std::string::npos)
    throw std::invalid_argument("config: [" + section + "] " + key + " = '" + trimmed(value) +
                                "': comments must be on a line of their own");
}

std::string iniLines(const std::string& unit, const std::string& doc, const std::string& name,
                     const std::string& value)
{
  return "# " + (unit.empty() ? "" : "[" + unit + "] ") + doc + "\n" + name + " = " + value + "\n";
}
}  // namespace detail

void checkKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& allowed)
{
  std::vector<std::string> sections;
  cfg.getAllSections(sections);
  for (const auto& s : sections)
    if (std::find(allowed.begin(), allowed.end(), s) == allowed.end())
      throw std::invalid_argument("config: unknown section [" + s + "]; known sections: " + detail::joined(allowed));
}

}  // namespace swslam::common
