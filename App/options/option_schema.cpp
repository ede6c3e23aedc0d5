#include "options/option_schema.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "geometry/error.h"
#include "geometry/json_writer.h"

namespace holefill {

namespace {

std::string kindName(OptionKind k) {
  switch (k) {
    case OptionKind::Number: return "number";
    case OptionKind::Integer: return "integer";
    case OptionKind::Bool: return "bool";
    case OptionKind::Choice: return "choice";
    case OptionKind::Text: return "text";
  }
  return "text";
}

std::string range(const OptionField& f) {
  const bool lo = std::isfinite(f.minimum), hi = std::isfinite(f.maximum);
  const auto n = [](double v) { return formatOptionNumber(v); };
  if (lo && hi) return "between " + n(f.minimum) + " and " + n(f.maximum);
  if (lo && f.minimum == 0) return f.minimumExcluded ? "positive" : "zero or positive";
  if (lo) return (f.minimumExcluded ? "above " : "at least ") + n(f.minimum);
  if (hi) return "at most " + n(f.maximum);
  return "finite";
}

void checkRange(const OptionField& f, double v, const std::string& text, const std::string& noun) {
  const bool ok = std::isfinite(v) && (f.minimumExcluded ? v > f.minimum : v >= f.minimum) && v <= f.maximum;
  if (!ok) throw Error(f.name + " must be " + (noun.empty() ? "" : noun + " ") + range(f) + ", got '" + text + "'");
}

}  // namespace

std::string formatOptionNumber(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // The shortest text that reads back to the same double: 1e-3 rather than 0.0010000000000000000208.
  for (int p = 1; p <= 17; ++p) {
    char s[40];
    std::snprintf(s, sizeof s, "%.*g", p, v);
    if (std::strtod(s, nullptr) == v) return s;
  }
  return buf;
}

double parseOptionNumber(const OptionField& f, const std::string& text) {
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) throw Error(f.name + " must be a number, got '" + text + "'");
  checkRange(f, v, text, "");
  return v;
}

int parseOptionInteger(const OptionField& f, const std::string& text) {
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || v != std::floor(v) || std::fabs(v) > 2e9)
    throw Error(f.name + " must be a whole number, got '" + text + "'");
  checkRange(f, v, text, "a whole number");
  return static_cast<int>(v);
}

bool parseOptionBool(const OptionField& f, const std::string& text) {
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  throw Error(f.name + " must be true or false, got '" + text + "'");
}

const std::string& checkOptionChoice(const OptionField& f, const std::string& text) {
  for (const auto& c : f.choices)
    if (c == text) return c;
  std::string list;
  for (const auto& c : f.choices) list += (list.empty() ? "" : ", ") + c;
  throw Error(f.name + " must be one of " + list + ", got '" + text + "'");
}

OptionField rangedField(const char* name, const char* flag, const char* unit, const char* doc, double minimum, double maximum,
                        bool minimumExcluded) {
  OptionField f{name, flag, OptionKind::Number, unit, doc};
  f.minimum = minimum;
  f.maximum = maximum;
  f.minimumExcluded = minimumExcluded;
  return f;
}

OptionField flagField(const char* name, const char* flag, bool flagSets, const char* doc) {
  OptionField f{name, flag, OptionKind::Bool, "", doc};
  f.flagSets = flagSets;
  return f;
}

[[noreturn]] void throwUnknownOption(const std::string& name, const std::vector<OptionField>& fields) {
  std::string list;
  for (const auto& f : fields) list += (list.empty() ? "" : ", ") + f.name;
  throw Error("unknown option '" + name + "': the options are " + list);
}

std::string OptionList::toJson() const {
  JsonWriter j;
  j.beginArray();
  for (size_t k = 0; k < fields.size(); ++k) {
    const OptionField& f = fields[k];
    j.beginObject()
        .field("name", f.name)
        .field("flag", f.flag)
        .field("kind", kindName(f.kind))
        .field("unit", f.unit)
        .field("doc", f.doc)
        .field("choices", f.choices);
    // An open end is null (JSON has no infinity).
    j.field("minimum", f.minimum).field("maximum", f.maximum).field("minimum_excluded", f.minimumExcluded).field("flag_sets", f.flagSets).key("default");
    const std::string& d = defaults[k];
    if (f.kind == OptionKind::Number) j.raw(d);
    else if (f.kind == OptionKind::Integer) j.value(std::stoi(d));
    else if (f.kind == OptionKind::Bool) j.value(d == "true");
    else j.value(d);
    j.endObject();
  }
  j.endArray();
  return j.str();
}

}  // namespace holefill
