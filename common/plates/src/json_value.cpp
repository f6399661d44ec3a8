#include "json_value.h"

#include <charconv>
#include <cmath>
#include <cstdint>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse::detail {
namespace {

constexpr int kMaxDepth = 64;

class Parser {
 public:
  Parser(const std::string& text, const std::string& name) : p_(text.data()), end_(p_ + text.size()), name_(name) {}

  JsonValue document() {
    JsonValue v = value(0);
    blanks();
    if (p_ != end_) fail("text after the end of the JSON document");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(format("'%s', line %zu: %s", name_.c_str(), line_, what.c_str()));
  }

  void blanks() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }

  bool take(char c) {
    blanks();
    if (p_ != end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }

  void expect(char c, const char* what) {
    if (!take(c)) fail(std::string("expected ") + what);
  }

  bool word(const char* w) {
    const size_t n = std::char_traits<char>::length(w);
    if (size_t(end_ - p_) >= n && std::equal(w, w + n, p_)) {
      p_ += n;
      return true;
    }
    return false;
  }

  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nested deeper than 64 levels");
    blanks();
    if (p_ == end_) fail("unexpected end of the file");
    JsonValue v;
    if (*p_ == '{') {
      ++p_;
      v.type = JsonValue::Type::Object;
      if (take('}')) return v;
      do {
        blanks();
        if (p_ == end_ || *p_ != '"') fail("expected a key in quotes");
        std::string key = string();
        expect(':', "':' after a key");
        if (v.fields.count(key)) fail("key \"" + key + "\" given twice");
        v.fields.emplace(std::move(key), value(depth + 1));
      } while (take(','));
      expect('}', "',' or '}' in an object");
    } else if (*p_ == '[') {
      ++p_;
      v.type = JsonValue::Type::Array;
      if (take(']')) return v;
      do v.items.push_back(value(depth + 1));
      while (take(','));
      expect(']', "',' or ']' in an array");
    } else if (*p_ == '"') {
      v.type = JsonValue::Type::String;
      v.text = string();
    } else if (word("true")) {
      v.type = JsonValue::Type::Bool;
      v.boolean = true;
    } else if (word("false")) {
      v.type = JsonValue::Type::Bool;
    } else if (word("null")) {
    } else {
      v.type = JsonValue::Type::Number;
      const auto [next, ec] = std::from_chars(p_, end_, v.number);
      if (ec != std::errc() || next == p_ || !std::isfinite(v.number)) fail("expected a value");
      p_ = next;
    }
    return v;
  }

  unsigned hex4() {
    if (end_ - p_ < 4) fail("a \\u escape needs 4 hex digits");
    unsigned u = 0;
    const auto [next, ec] = std::from_chars(p_, p_ + 4, u, 16);
    if (ec != std::errc() || next != p_ + 4) fail("a \\u escape needs 4 hex digits");
    p_ += 4;
    return u;
  }

  void utf8(std::string& s, uint32_t c) {
    if (c < 0x80) {
      s += char(c);
    } else if (c < 0x800) {
      s += char(0xC0 | (c >> 6));
      s += char(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      s += char(0xE0 | (c >> 12));
      s += char(0x80 | ((c >> 6) & 0x3F));
      s += char(0x80 | (c & 0x3F));
    } else {
      s += char(0xF0 | (c >> 18));
      s += char(0x80 | ((c >> 12) & 0x3F));
      s += char(0x80 | ((c >> 6) & 0x3F));
      s += char(0x80 | (c & 0x3F));
    }
  }

  std::string string() {
    ++p_;  // the opening quote
    std::string s;
    while (true) {
      if (p_ == end_) fail("a string does not end");
      const char c = *p_++;
      if (c == '"') return s;
      if (c == '\n' || (unsigned char)c < 0x20) fail("a control character inside a string");
      if (c != '\\') {
        s += c;
        continue;
      }
      if (p_ == end_) fail("a string does not end");
      switch (const char e = *p_++) {
        case '"': case '\\': case '/': s += e; break;
        case 'b': s += '\b'; break;
        case 'f': s += '\f'; break;
        case 'n': s += '\n'; break;
        case 'r': s += '\r'; break;
        case 't': s += '\t'; break;
        case 'u': {
          uint32_t c1 = hex4();
          if (c1 >= 0xD800 && c1 < 0xDC00 && end_ - p_ >= 6 && p_[0] == '\\' && p_[1] == 'u') {
            p_ += 2;
            const uint32_t c2 = hex4();
            if (c2 < 0xDC00 || c2 >= 0xE000) fail("a \\u surrogate pair is broken");
            c1 = 0x10000 + ((c1 - 0xD800) << 10) + (c2 - 0xDC00);
          }
          utf8(s, c1);
          break;
        }
        default: fail(std::string("unknown escape \\") + e + " in a string");
      }
    }
  }

  const char* p_;
  const char* end_;
  std::string name_;
  size_t line_ = 1;
};

const char* type_name(JsonValue::Type t) {
  switch (t) {
    case JsonValue::Type::Null: return "null";
    case JsonValue::Type::Bool: return "true or false";
    case JsonValue::Type::Number: return "a number";
    case JsonValue::Type::String: return "a string";
    case JsonValue::Type::Array: return "a list";
    case JsonValue::Type::Object: return "an object";
  }
  return "";
}

void want(const JsonValue& v, JsonValue::Type t, const std::string& where) {
  if (v.type != t) throw Error(where + " is " + type_name(v.type) + ", not " + type_name(t));
}

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
  const auto i = fields.find(key);
  return i == fields.end() ? nullptr : &i->second;
}

const JsonValue& JsonValue::at(const std::string& key, const std::string& where) const {
  want(*this, Type::Object, where);
  const JsonValue* v = find(key);
  if (!v) throw Error(where + " has no \"" + key + "\"");
  return *v;
}

double JsonValue::as_number(const std::string& where) const {
  want(*this, Type::Number, where);
  return number;
}

const std::string& JsonValue::as_string(const std::string& where) const {
  want(*this, Type::String, where);
  return text;
}

const std::vector<JsonValue>& JsonValue::as_array(const std::string& where) const {
  want(*this, Type::Array, where);
  return items;
}

JsonValue parse_json(const std::string& text, const std::string& name) { return Parser(text, name).document(); }

}  // namespace slicereuse::detail
