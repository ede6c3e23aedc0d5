// A minimal streaming JSON writer for reports. The core renders each report
// once, as JSON; the CLI prints it and the Python module hands it to json.loads,
// so both doors show the same fields. Non-finite numbers are written as null.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace holefill {

class JsonWriter {
public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(const std::string& k);
  JsonWriter& value(const std::string& v);
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& value(double v);
  JsonWriter& value(int v);
  JsonWriter& value(bool v);
  JsonWriter& value(const std::vector<int>& v);
  JsonWriter& value(const std::vector<std::string>& v);
  // A value rendered by another writer (a nested report), inserted as it is.
  JsonWriter& raw(const std::string& json);
  template <class T> JsonWriter& field(const std::string& k, const T& v) { key(k); return value(v); }
  std::string str() const { return out_.str(); }

private:
  void separator();
  void writeString(const std::string& v);
  std::ostringstream out_;
  std::vector<bool> first_;  // per open container: no element written yet
  bool afterKey_ = false;
};

}  // namespace holefill
