// A small JSON value for summary.json and the cable tool's output: objects keep their insertion order so that the
// files read top-down the way they were written.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace halfeti::io {

class Json {
 public:
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };

  Json() = default;
  Json(bool b) : type_(Type::kBool), bool_(b) {}                                // NOLINT(runtime/explicit)
  Json(double x) : type_(Type::kNumber), number_(x) {}                          // NOLINT
  Json(int x) : type_(Type::kNumber), number_(x) {}                             // NOLINT
  Json(long x) : type_(Type::kNumber), number_(static_cast<double>(x)) {}       // NOLINT
  Json(long long x) : type_(Type::kNumber), number_(static_cast<double>(x)) {}  // NOLINT
  Json(unsigned long x) : type_(Type::kNumber), number_(static_cast<double>(x)) {}  // NOLINT
  Json(const char* s) : type_(Type::kString), string_(s) {}                         // NOLINT
  Json(std::string s) : type_(Type::kString), string_(std::move(s)) {}              // NOLINT

  static Json array() {
    Json j;
    j.type_ = Type::kArray;
    return j;
  }
  static Json object() {
    Json j;
    j.type_ = Type::kObject;
    return j;
  }

  // Object: sets (or replaces) a member. Array: appends.
  Json& set(const std::string& key, Json value);
  Json& push(Json value);
  const Json* find(const std::string& key) const;

  Type type() const { return type_; }
  double number() const { return number_; }
  const std::string& string() const { return string_; }
  const std::vector<Json>& items() const { return items_; }
  const std::vector<std::pair<std::string, Json>>& members() const { return members_; }

  // Non-finite numbers are written as null (JSON has no NaN); indent 0 writes one line.
  std::string dump(int indent = 2) const;

 private:
  void write(std::string& out, int indent, int depth) const;
  Type type_ = Type::kNull;
  bool bool_ = false;
  double number_ = 0.0;
  std::string string_;
  std::vector<Json> items_;
  std::vector<std::pair<std::string, Json>> members_;
};

}  // namespace halfeti::io
