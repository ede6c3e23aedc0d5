// An option set declared once (STYLE.md 11): each field of a core *Options struct with the name
// the API spells it by (the Python keyword; capitalized, the FreeCAD document property), its CLI
// flag, kind, unit, range, one-line doc, and the two functions that read and write it in the
// struct. The default is the struct's own (read from a default-constructed one), so changing a
// default is a one-line change in the core that every door — the CLI's flags and `holefill
// options`, the pybind keyword dictionaries, the Python signatures, the document objects'
// properties and the task panels' tooltips — sees. Values cross the doors as text (numbers in
// round-trip precision, bools true/false) and are checked here, once, with the field named.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace holefill {

enum class OptionKind { Number, Integer, Bool, Choice, Text };

struct OptionField {
  std::string name;    // the API's spelling, e.g. "angularTolerance"
  std::string flag;    // the CLI's, e.g. "--angular-tolerance"; empty where the command line has none
  OptionKind kind = OptionKind::Number;
  std::string unit;    // "model units", "radians", "of the diagonal", ... ; empty where there is none
  std::string doc;     // one line, for tooltips, `holefill options` and docstrings
  std::vector<std::string> choices;  // Choice: the accepted values, as the API spells them
  double minimum = -std::numeric_limits<double>::infinity();  // Number, Integer
  double maximum = std::numeric_limits<double>::infinity();
  bool minimumExcluded = false;  // a tolerance that 0 would make unreachable: > minimum
  bool flagSets = true;          // Bool: the value a bare flag sets (--no-crease-detection sets false)
};

template <class O>
struct OptionBinding {
  OptionField field;
  std::function<std::string(const O&)> get;         // the value as text
  std::function<void(O&, const std::string&)> set;  // from text; throws Error naming the field
};

template <class O>
using OptionSchema = std::vector<OptionBinding<O>>;

// Text of values, and their checks against a field (Error naming the field and what it takes).
std::string formatOptionNumber(double v);  // round-trip precision
double parseOptionNumber(const OptionField& f, const std::string& text);
int parseOptionInteger(const OptionField& f, const std::string& text);
bool parseOptionBool(const OptionField& f, const std::string& text);
const std::string& checkOptionChoice(const OptionField& f, const std::string& text);

// A schema's fields with their defaults (as text), free of the struct: what the doors list.
struct OptionList {
  std::vector<OptionField> fields;
  std::vector<std::string> defaults;  // one per field
  // [{"name", "flag", "kind", "unit", "doc", "choices", "minimum", "maximum", "minimum_excluded",
  // "flag_sets", "default"}, ...], the default typed (number, bool or string).
  std::string toJson() const;
};

[[noreturn]] void throwUnknownOption(const std::string& name, const std::vector<OptionField>& fields);

// The defaults are read from a default-constructed O.
template <class O>
OptionList optionList(const OptionSchema<O>& s) {
  const O defaults{};
  OptionList l;
  for (const auto& b : s) {
    l.fields.push_back(b.field);
    l.defaults.push_back(b.get(defaults));
  }
  return l;
}

template <class O>
std::string optionSchemaJson(const OptionSchema<O>& s) {
  return optionList(s).toJson();
}

// Sets the field named `name` (the API's spelling) from text. Throws Error for an unknown name
// (listing the known ones) or a value the field refuses.
template <class O>
void setOption(const OptionSchema<O>& s, O& o, const std::string& name, const std::string& text) {
  for (const auto& b : s)
    if (b.field.name == name) return b.set(o, text);
  throwUnknownOption(name, optionList(s).fields);
}

// Fields with a range ([minimum, maximum], the minimum excluded when asked; numberOption and
// integerOption set the kind), and Bool fields whose bare CLI flag sets `flagSets`.
OptionField rangedField(const char* name, const char* flag, const char* unit, const char* doc,
                        double minimum = -std::numeric_limits<double>::infinity(),
                        double maximum = std::numeric_limits<double>::infinity(), bool minimumExcluded = false);
OptionField flagField(const char* name, const char* flag, bool flagSets, const char* doc);

// Bindings of the common kinds to a member reached by `at` (get reads through it, never writes),
// and of a Choice to its own get/set
// (the text is checked against the choices before `set` sees it).
template <class O>
OptionBinding<O> numberOption(OptionField f, std::function<double&(O&)> at) {
  f.kind = OptionKind::Number;
  return {f, [at](const O& o) { return formatOptionNumber(at(const_cast<O&>(o))); },
          [f, at](O& o, const std::string& t) { at(o) = parseOptionNumber(f, t); }};
}

template <class O>
OptionBinding<O> integerOption(OptionField f, std::function<int&(O&)> at) {
  f.kind = OptionKind::Integer;
  return {f, [at](const O& o) { return std::to_string(at(const_cast<O&>(o))); },
          [f, at](O& o, const std::string& t) { at(o) = parseOptionInteger(f, t); }};
}

template <class O>
OptionBinding<O> boolOption(OptionField f, std::function<bool&(O&)> at) {
  f.kind = OptionKind::Bool;
  return {f, [at](const O& o) { return std::string(at(const_cast<O&>(o)) ? "true" : "false"); },
          [f, at](O& o, const std::string& t) { at(o) = parseOptionBool(f, t); }};
}

template <class O>
OptionBinding<O> choiceOption(OptionField f, std::function<std::string(const O&)> get, std::function<void(O&, const std::string&)> set) {
  f.kind = OptionKind::Choice;
  return {f, std::move(get), [f, set](O& o, const std::string& t) { set(o, checkOptionChoice(f, t)); }};
}

template <class O>
OptionBinding<O> textOption(OptionField f, std::function<std::string&(O&)> at) {
  f.kind = OptionKind::Text;
  return {f, [at](const O& o) { return at(const_cast<O&>(o)); }, [at](O& o, const std::string& t) { at(o) = t; }};
}

}  // namespace holefill
