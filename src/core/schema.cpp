#include "halfeti/core/schema.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "halfeti/core/error.hpp"

namespace halfeti::scene {

namespace {
std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}
}  // namespace

Key Key::real(std::string name, std::string doc, std::string unit) {
  Key k(std::move(name), std::move(doc), ValueKind::kReal);
  k.unit_ = std::move(unit);
  return k;
}
Key Key::integer(std::string name, std::string doc) {
  return Key(std::move(name), std::move(doc), ValueKind::kInteger);
}
Key Key::boolean(std::string name, std::string doc) {
  return Key(std::move(name), std::move(doc), ValueKind::kBool);
}
Key Key::string(std::string name, std::string doc) {
  return Key(std::move(name), std::move(doc), ValueKind::kString);
}
Key Key::choice(std::string name, std::string doc, std::vector<std::string> choices) {
  Key k(std::move(name), std::move(doc), ValueKind::kChoice);
  k.choices_ = std::move(choices);
  return k;
}
Key Key::point(std::string name, std::string doc, std::string unit) {
  Key k(std::move(name), std::move(doc), ValueKind::kPoint);
  k.unit_ = std::move(unit);
  return k;
}
Key Key::reals(std::string name, std::string doc, std::string unit) {
  Key k(std::move(name), std::move(doc), ValueKind::kRealList);
  k.unit_ = std::move(unit);
  return k;
}
Key Key::section(std::string name, std::string doc, std::shared_ptr<const Schema> schema) {
  Key k(std::move(name), std::move(doc), ValueKind::kSection);
  k.schema_ = std::move(schema);
  return k;
}
Key Key::list(std::string name, std::string doc, std::shared_ptr<const Schema> item) {
  Key k(std::move(name), std::move(doc), ValueKind::kList);
  k.schema_ = std::move(item);
  return k;
}

Key& Key::required() {
  required_ = true;
  return *this;
}
Key& Key::always() {
  always_ = true;
  return *this;
}
Key& Key::implied_by(std::vector<std::string> siblings) {
  implied_by_ = std::move(siblings);
  return *this;
}

Key& Key::def(double v) {
  // The shortest text that reads back to the same double, so resolved scenes show 0.005, not 0.0050000000000000001.
  char buf[40];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  default_ = buf;
  return *this;
}
Key& Key::def(int v) {
  default_ = std::to_string(v);
  return *this;
}
Key& Key::def(bool v) {
  default_ = v ? "true" : "false";
  return *this;
}
Key& Key::def(const char* v) {
  return def(std::string(v));
}
Key& Key::def(const std::string& v) {
  default_ = v;
  return *this;
}
Key& Key::def_point(double x, double y) {
  default_ = "[" + format_number(x) + ", " + format_number(y) + "]";
  return *this;
}
Key& Key::def_yaml(const std::string& yaml_text) {
  default_ = yaml_text;
  return *this;
}
Key& Key::positive() {
  return above(0.0);
}
Key& Key::non_negative() {
  return at_least(0.0);
}
Key& Key::at_least(double lo) {
  lo_ = lo;
  lo_open_ = false;
  return *this;
}
Key& Key::above(double lo) {
  lo_ = lo;
  lo_open_ = true;
  return *this;
}
Key& Key::at_most(double hi) {
  hi_ = hi;
  hi_open_ = false;
  return *this;
}
Key& Key::below(double hi) {
  hi_ = hi;
  hi_open_ = true;
  return *this;
}
Key& Key::in(double lo, double hi) {
  at_least(lo);
  return at_most(hi);
}
Key& Key::min_items(int n) {
  min_items_ = n;
  return *this;
}

std::string Key::expectation() const {
  std::ostringstream os;
  auto range = [&]() {
    const bool has_lo = std::isfinite(lo_), has_hi = std::isfinite(hi_);
    if (has_lo && has_hi && !lo_open_ && !hi_open_)
      os << " in [" << lo_ << ", " << hi_ << "]";
    else {
      if (has_lo) os << (lo_open_ ? " > " : " >= ") << lo_;
      if (has_lo && has_hi) os << " and";
      if (has_hi) os << (hi_open_ ? " < " : " <= ") << hi_;
    }
  };
  switch (kind_) {
    case ValueKind::kReal:
      os << "a number";
      range();
      break;
    case ValueKind::kInteger:
      os << "a whole number";
      range();
      break;
    case ValueKind::kBool:
      os << "true or false";
      break;
    case ValueKind::kString:
      os << "a string";
      break;
    case ValueKind::kChoice: {
      os << "one of ";
      for (size_t i = 0; i < choices_.size(); ++i) os << (i ? ", " : "") << choices_[i];
      break;
    }
    case ValueKind::kPoint:
      os << "a point [x, y]";
      break;
    case ValueKind::kRealList:
      os << "a list of numbers";
      if (min_items_ > 0) os << " (at least " << min_items_ << ")";
      range();
      break;
    case ValueKind::kSection:
      os << "a section (key: value lines)";
      break;
    case ValueKind::kList:
      os << "a list of sections";
      if (min_items_ > 0) os << " (at least " << min_items_ << ")";
      break;
  }
  if (!unit_.empty()) os << " (" << unit_ << ")";
  return os.str();
}

Schema& Schema::add(Key key) {
  HALFETI_CHECK(find(key.name()) == nullptr, "schema key '" << key.name() << "' declared twice");
  keys_.push_back(std::move(key));
  return *this;
}

Schema& Schema::discriminator(const std::string& key) {
  const Key* k = find(key);
  HALFETI_CHECK(k && k->kind() == ValueKind::kChoice, "discriminator '" << key << "' must be a choice key");
  discriminator_ = key;
  return *this;
}

Schema& Schema::variant(const std::string& value, std::shared_ptr<const Schema> extra) {
  HALFETI_CHECK(!discriminator_.empty(), "variant '" << value << "' added before the discriminator");
  const Key* k = find(discriminator_);
  HALFETI_CHECK(std::find(k->choices().begin(), k->choices().end(), value) != k->choices().end(),
                "variant '" << value << "' is not a choice of '" << discriminator_ << "'");
  variants_[value] = std::move(extra);
  return *this;
}

const Key* Schema::find(const std::string& name) const {
  for (const auto& k : keys_)
    if (k.name() == name) return &k;
  return nullptr;
}

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
  // Edit distance with adjacent transpositions (optimal string alignment): 'heigth' is one edit from 'height'.
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
      for (size_t j = 1; j <= b.size(); ++j) {
        d[i][j] =
            std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
          d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    return d[a.size()][b.size()];
  };
  std::string best;
  size_t best_d = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const size_t d = distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

}  // namespace halfeti::scene
