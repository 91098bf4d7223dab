#pragma once
// A module's parameters, declared once: each key of its .ini section is one row of a table
// (its name, the struct member that holds it, its unit, its range, one line of doc, and its
// tier: a key a user tunes, or one only an expert does). Loading, checking, writing and the
// documented defaults (config/default.ini, config/expert.ini) all come from the table.
//
// Loading is strict: an unknown key is an error naming the valid ones, a value that is not of
// its key's kind is an error (MRPT's readers would take "abc" as 0 and "2.5" as 2 silently),
// and so is a value out of the key's range. A key that is absent keeps the struct's in-class
// default. Angles are held in radians and spelled in degrees in the file (a name ending in
// _DEG, MRPT's convention).

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace swslam::common
{
/** Who tunes a key: config/default.ini shows the user's keys, config/expert.ini the rest. */
enum class Tier
{
  User,
  Expert
};

/** The numbers a key accepts: from lo to hi, either end open or closed. An infinite end that
 * is closed accepts that infinity (Barron's shape -inf); otherwise values are finite. */
struct Range
{
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = true, hi_open = true;

  bool contains(double v) const;
  /** "in [0, 1]", "> 0", ">= 1", or "" for any finite number. */
  std::string describe() const;
};
Range anyNumber();
Range atLeast(double lo);
Range above(double lo);
Range between(double lo, double hi);  ///< [lo, hi]
Range aboveUpTo(double lo, double hi);  ///< (lo, hi]
Range strictlyBetween(double lo, double hi);  ///< (lo, hi)

/** The shortest decimal text of `v` that reads back as `v` ("0.1", "1e-06", "inf"). */
std::string shortestText(double v);
/** The shortest decimal text of degrees d with DEG2RAD(d) == radians exactly. */
std::string degreesText(double radians);

namespace detail
{
/** One row, as the loader and the writers use it whatever the struct. */
template <class P>
struct Row
{
  std::string name, unit, doc;
  Tier tier = Tier::Expert;
  Range range;  ///< of the member's numbers (radians for angles)
  Range shown;  ///< the same as the file spells them (degrees for angles)
  std::string kind;  ///< "number", "integer", "boolean" or "one of: a, b"
  /** Reads `value` into the struct; an error text if it is not of the key's kind. */
  std::function<std::string(P&, const std::string& value)> parse;
  /** The member's number that `range` applies to, if the key is a number. */
  std::function<std::optional<double>(const P&)> number;
  /** The value as the file spells it. */
  std::function<std::string(const P&)> text;
};

/** The text errors of a value read as kinds: empty when fine. */
std::string parseNumber(const std::string& value, double& out);
std::string parseInteger(const std::string& value, long long& out);
std::string parseBoolean(const std::string& value, bool& out);
std::string trimmed(const std::string& s);
/** Throws std::invalid_argument for a value that carries a comment on its line. */
void checkNoInlineComment(const std::string& section, const std::string& key, const std::string& value);
std::string joined(const std::vector<std::string>& v);
bool sameName(const std::string& a, const std::string& b);  ///< case-insensitive, as MRPT's reader
double deg2rad(double d);
/** The comment and key lines of one key in a written section. */
std::string iniLines(const std::string& unit, const std::string& doc, const std::string& name,
                     const std::string& value);
}  // namespace detail

template <class P>
class ParamTable
{
 public:
  /** `section`: the .ini section; `title`: one line saying what the module does. */
  ParamTable(std::string section, std::string title) : section_(std::move(section)), title_(std::move(title)) {}

  ParamTable& real(std::string name, double P::*m, std::string unit, Range r, std::string doc,
                   Tier tier = Tier::Expert)
  {
    detail::Row<P> row{std::move(name), std::move(unit), std::move(doc), tier, r, r, "number", {}, {}, {}};
    row.parse = [m](P& p, const std::string& v) { return detail::parseNumber(v, p.*m); };
    row.number = [m](const P& p) { return std::optional<double>(p.*m); };
    row.text = [m](const P& p) { return shortestText(p.*m); };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** A key held in radians and written in degrees: `name` ends in _DEG, `r` is in degrees. */
  ParamTable& angle(std::string name, double P::*m, Range r, std::string doc, Tier tier = Tier::Expert)
  {
    const Range radians{detail::deg2rad(r.lo), detail::deg2rad(r.hi), r.lo_open, r.hi_open};
    detail::Row<P> row{std::move(name), "deg", std::move(doc), tier, radians, r, "number", {}, {}, {}};
    row.parse = [m](P& p, const std::string& v) {
      double d = 0;
      std::string problem = detail::parseNumber(v, d);
      if (problem.empty()) p.*m = detail::deg2rad(d);
      return problem;
    };
    row.number = [m](const P& p) { return std::optional<double>(p.*m); };
    row.text = [m](const P& p) { return degreesText(p.*m); };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** An integer key of any integral member type. */
  template <class I>
  ParamTable& integer(std::string name, I P::*m, std::string unit, Range r, std::string doc,
                      Tier tier = Tier::Expert)
  {
    detail::Row<P> row{std::move(name), std::move(unit), std::move(doc), tier, r, r, "integer", {}, {}, {}};
    row.parse = [m, r](P& p, const std::string& v) {
      long long x = 0;
      std::string problem = detail::parseInteger(v, x);
      // Out of range values are named by the range check; only the member's own type bounds
      // are checked here, so that nothing wraps on assignment.
      if (problem.empty() && !r.contains(static_cast<double>(x)))
        return std::string("must be ") + r.describe();
      if (problem.empty()) p.*m = static_cast<I>(x);
      return problem;
    };
    row.number = [m](const P& p) { return std::optional<double>(static_cast<double>(p.*m)); };
    row.text = [m](const P& p) { return std::to_string(p.*m); };
    rows_.push_back(std::move(row));
    return *this;
  }

  ParamTable& flag(std::string name, bool P::*m, std::string doc, Tier tier = Tier::Expert)
  {
    detail::Row<P> row{std::move(name), "", std::move(doc), tier, {}, {}, "boolean", {}, {}, {}};
    row.parse = [m](P& p, const std::string& v) { return detail::parseBoolean(v, p.*m); };
    row.number = [](const P&) { return std::optional<double>(); };
    row.text = [m](const P& p) { return std::string(p.*m ? "true" : "false"); };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** A key that takes one of a few names, each standing for a value of the member's type. */
  template <class E>
  ParamTable& choice(std::string name, E P::*m, std::vector<std::pair<std::string, E>> names, std::string doc,
                     Tier tier = Tier::Expert)
  {
    std::vector<std::string> spelled;
    for (const auto& n : names) spelled.push_back(n.first);
    detail::Row<P> row{std::move(name), "", std::move(doc), tier, {}, {}, "one of: " + detail::joined(spelled), {}, {}, {}};
    row.parse = [m, names, spelled](P& p, const std::string& v) {
      for (const auto& [n, e] : names)
        if (n == v)
        {
          p.*m = e;
          return std::string();
        }
      return "is not one of: " + detail::joined(spelled);
    };
    row.number = [](const P&) { return std::optional<double>(); };
    row.text = [m, names](const P& p) {
      for (const auto& [n, e] : names)
        if (p.*m == e) return n;
      return std::string("?");
    };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** A key of free text (a sensor's label): any value, trimmed. */
  ParamTable& text(std::string name, std::string P::*m, std::string doc, Tier tier = Tier::Expert)
  {
    detail::Row<P> row{std::move(name), "", std::move(doc), tier, {}, {}, "text", {}, {}, {}};
    row.parse = [m](P& p, const std::string& v) {
      p.*m = v;
      return std::string();
    };
    row.number = [](const P&) { return std::optional<double>(); };
    row.text = [m](const P& p) { return p.*m; };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** A key of its own form: `parse` reads a value into the struct (returning what is wrong
   * with it, empty if nothing), `format` writes it as `parse` reads it back. */
  ParamTable& custom(std::string name, std::function<std::string(P&, const std::string&)> parse,
                     std::function<std::string(const P&)> format, std::string doc, Tier tier = Tier::Expert)
  {
    detail::Row<P> row{std::move(name), "", std::move(doc), tier, {}, {}, "text", std::move(parse), {}, std::move(format)};
    row.number = [](const P&) { return std::optional<double>(); };
    rows_.push_back(std::move(row));
    return *this;
  }

  /** A rule between keys of the section: `what` says it when `ok` is false. */
  ParamTable& rule(std::function<bool(const P&)> ok, std::string what)
  {
    rules_.push_back({std::move(ok), std::move(what)});
    return *this;
  }

  const std::string& section() const { return section_; }
  const std::string& title() const { return title_; }

  /** The section's values from `cfg` over `p` (absent keys keep their values), then check().
   * Unknown keys are named first, then the keys' values in the table's order. */
  void load(const mrpt::config::CConfigFileBase& cfg, P& p) const
  {
    std::vector<std::string> present;
    cfg.getAllKeys(section_, present);
    for (const auto& padded : present)
      if (!find(detail::trimmed(padded)))
        throw std::invalid_argument("config: unknown key '" + detail::trimmed(padded) + "' in section [" + section_ +
                                    "]; known keys: " + detail::joined(names()));
    for (const auto& row : rows_)
      for (const auto& padded : present)
      {
        if (!detail::sameName(row.name, detail::trimmed(padded))) continue;
        const std::string raw = cfg.read_string(section_, padded, "");
        detail::checkNoInlineComment(section_, row.name, raw);
        const std::string value = detail::trimmed(raw);
        const std::string problem = row.parse(p, value);
        if (!problem.empty())
          throw std::invalid_argument("config: [" + section_ + "] " + row.name + " = '" + value + "' " + problem);
      }
    check(p);
  }

  P load(const mrpt::config::CConfigFileBase& cfg) const
  {
    P p;
    load(cfg, p);
    return p;
  }

  /** For files whose every key is required (a simulator scenario): throws
   * std::invalid_argument "missing section [s]" or "missing key [s] k" unless the section
   * and every key but `optional` ones are in `cfg`. */
  void requireAll(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& optional = {}) const
  {
    if (!cfg.sectionExists(section_)) throw std::invalid_argument("missing section [" + section_ + "]");
    for (const auto& row : rows_)
      if (!cfg.keyExists(section_, row.name) &&
          std::find(optional.begin(), optional.end(), row.name) == optional.end())
        throw std::invalid_argument("missing key [" + section_ + "] " + row.name);
  }

  /** Throws std::invalid_argument naming the first key out of its range or rule broken. */
  void check(const P& p) const
  {
    for (const auto& row : rows_)
      if (const auto v = row.number(p); v && !row.range.contains(*v))
        throw std::invalid_argument("config [" + section_ + "]: " + row.name + " must be " + row.shown.describe() +
                                    (row.unit.empty() ? "" : " " + row.unit) + ", got " + row.text(p));
    for (const auto& [ok, what] : rules_)
      if (!ok(p)) throw std::invalid_argument("config [" + section_ + "]: " + what);
  }

  /** Writes every key's value of `p`. */
  void save(const P& p, mrpt::config::CConfigFileBase& cfg) const
  {
    for (const auto& row : rows_) cfg.write(section_, row.name, row.text(p));
  }

  /** The section as the shipped files show it: its title, then per key of `tier` a comment
   * line ([unit] doc) and the key with its value in `p`; empty if the tier has no key here. */
  std::string ini(const P& p, Tier tier) const
  {
    std::string body;
    for (const auto& row : rows_)
      if (row.tier == tier) body += detail::iniLines(row.unit, row.doc, row.name, row.text(p));
    return body.empty() ? body : "[" + section_ + "]\n# " + title_ + "\n" + body;
  }

  /** The keys' names, in table order. */
  std::vector<std::string> names() const
  {
    std::vector<std::string> out;
    for (const auto& row : rows_) out.push_back(row.name);
    return out;
  }
  /** The names of the keys of one tier. */
  std::vector<std::string> names(Tier tier) const
  {
    std::vector<std::string> out;
    for (const auto& row : rows_)
      if (row.tier == tier) out.push_back(row.name);
    return out;
  }

 private:
  const detail::Row<P>* find(const std::string& key) const
  {
    for (const auto& row : rows_)
      if (detail::sameName(row.name, key)) return &row;
    return nullptr;
  }

  std::string section_, title_;
  std::vector<detail::Row<P>> rows_;
  std::vector<std::pair<std::function<bool(const P&)>, std::string>> rules_;
};

/** Throws std::invalid_argument if `cfg` has a section not in `allowed`. */
void checkKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& allowed);

}  // namespace swslam::common
