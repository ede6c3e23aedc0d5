#include "geometry/json_writer.h"

#include <cmath>
#include <iomanip>

namespace holefill {

void JsonWriter::separator() {
  if (afterKey_) { afterKey_ = false; return; }
  if (!first_.empty()) {
    if (!first_.back()) out_ << ',';
    first_.back() = false;
  }
}

JsonWriter& JsonWriter::beginObject() { separator(); out_ << '{'; first_.push_back(true); return *this; }
JsonWriter& JsonWriter::endObject() { out_ << '}'; first_.pop_back(); return *this; }
JsonWriter& JsonWriter::beginArray() { separator(); out_ << '['; first_.push_back(true); return *this; }
JsonWriter& JsonWriter::endArray() { out_ << ']'; first_.pop_back(); return *this; }

JsonWriter& JsonWriter::key(const std::string& k) {
  separator();
  writeString(k);
  out_ << ':';
  afterKey_ = true;
  return *this;
}

JsonWriter& JsonWriter::raw(const std::string& json) {
  separator();
  out_ << json;
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& v) {
  separator();
  writeString(v);
  return *this;
}

void JsonWriter::writeString(const std::string& v) {
  out_ << '"';
  for (char c : v) {
    switch (c) {
      case '"': out_ << "\\\""; break;
      case '\\': out_ << "\\\\"; break;
      case '\n': out_ << "\\n"; break;
      case '\t': out_ << "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out_ << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
        else out_ << c;
    }
  }
  out_ << '"';
}

JsonWriter& JsonWriter::value(double v) {
  separator();
  if (std::isfinite(v)) out_ << std::setprecision(17) << v; else out_ << "null";
  return *this;
}

JsonWriter& JsonWriter::value(int v) { separator(); out_ << v; return *this; }
JsonWriter& JsonWriter::value(bool v) { separator(); out_ << (v ? "true" : "false"); return *this; }

JsonWriter& JsonWriter::value(const std::vector<int>& v) {
  beginArray();
  for (int x : v) value(x);
  return endArray();
}

JsonWriter& JsonWriter::value(const std::vector<std::string>& v) {
  beginArray();
  for (const auto& x : v) value(x);
  return endArray();
}

}  // namespace holefill
