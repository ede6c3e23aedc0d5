#include "geometry/json_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "geometry/error.h"

namespace holefill {

const JsonValue* JsonValue::find(const std::string& key) const {
  if (type != Type::Object) return nullptr;
  for (const auto& [k, v] : object)
    if (k == key) return &v;
  return nullptr;
}

namespace {

struct Reader {
  const std::string& s;
  const std::string& name;
  size_t i = 0;
  int depth = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw Error("'" + name + "' is not valid JSON: " + what + " at character " + std::to_string(i + 1));
  }
  void skip() {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  }
  bool literal(const char* word) {
    const std::string w(word);
    if (s.compare(i, w.size(), w) != 0) return false;
    i += w.size();
    return true;
  }
  std::string text() {
    ++i;  // opening quote
    std::string out;
    while (i < s.size() && s[i] != '"') {
      if (static_cast<unsigned char>(s[i]) < 0x20) fail("a control character inside a string");
      if (s[i] == '\\') {
        if (++i >= s.size()) break;
        const char e = s[i];
        const char* from = "\"\\/bfnrt";
        const char* to = "\"\\/\b\f\n\r\t";
        const char* at = std::strchr(from, e);
        if (e == 'u') {
          out += "\\u";
        } else if (at && *at) {
          out += to[at - from];
        } else {
          fail("an unknown escape");
        }
      } else {
        out += s[i];
      }
      ++i;
    }
    if (i >= s.size()) fail("an unterminated string");
    ++i;
    return out;
  }
  JsonValue value() {
    if (++depth > 200) fail("nesting deeper than 200");
    skip();
    if (i >= s.size()) fail("the text ends where a value should be");
    JsonValue v;
    const char c = s[i];
    if (c == '{') {
      v.type = JsonValue::Type::Object;
      ++i;
      skip();
      if (i < s.size() && s[i] == '}') {
        ++i;
      } else {
        for (;;) {
          skip();
          if (i >= s.size() || s[i] != '"') fail("an object key (a string) expected");
          std::string key = text();
          skip();
          if (i >= s.size() || s[i] != ':') fail("':' expected");
          ++i;
          v.object.emplace_back(std::move(key), value());
          skip();
          if (i < s.size() && s[i] == ',') { ++i; continue; }
          if (i < s.size() && s[i] == '}') { ++i; break; }
          fail("',' or '}' expected");
        }
      }
    } else if (c == '[') {
      v.type = JsonValue::Type::Array;
      ++i;
      skip();
      if (i < s.size() && s[i] == ']') {
        ++i;
      } else {
        for (;;) {
          v.array.push_back(value());
          skip();
          if (i < s.size() && s[i] == ',') { ++i; continue; }
          if (i < s.size() && s[i] == ']') { ++i; break; }
          fail("',' or ']' expected");
        }
      }
    } else if (c == '"') {
      v.type = JsonValue::Type::String;
      v.string = text();
    } else if (literal("true")) {
      v.type = JsonValue::Type::Bool;
      v.boolean = true;
    } else if (literal("false")) {
      v.type = JsonValue::Type::Bool;
    } else if (literal("null")) {
    } else {
      const char* start = s.c_str() + i;
      char* end = nullptr;
      v.number = std::strtod(start, &end);
      if (end == start || !(c == '-' || std::isdigit(static_cast<unsigned char>(c)))) fail("a value expected");
      if (!std::isfinite(v.number)) fail("a number out of range");
      v.type = JsonValue::Type::Number;
      i += static_cast<size_t>(end - start);
    }
    --depth;
    return v;
  }
};

}  // namespace

JsonValue parseJson(const std::string& text, const std::string& name) {
  Reader r{text, name};
  JsonValue v = r.value();
  r.skip();
  if (r.i != text.size()) r.fail("text after the value");
  return v;
}

}  // namespace holefill
