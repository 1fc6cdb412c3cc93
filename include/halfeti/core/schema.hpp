// The scene schema: what keys a scene may hold, their types, units, defaults and ranges.
//
// Each module declares the keys of its own section with the builder below; the application joins the sections
// into the scene schema. `resolve()` checks a raw YAML tree against a schema and returns the resolved tree with
// every default filled in, or throws UserError naming file, line, key, what was found and what was expected.
#pragma once

#include <yaml-cpp/yaml.h>

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace halfeti::scene {

class Schema;

enum class ValueKind { kReal, kInteger, kBool, kString, kChoice, kPoint, kRealList, kSection, kList };

// One key of a section.
class Key {
 public:
  static Key real(std::string name, std::string doc, std::string unit = "");
  static Key integer(std::string name, std::string doc);
  static Key boolean(std::string name, std::string doc);
  static Key string(std::string name, std::string doc);
  static Key choice(std::string name, std::string doc, std::vector<std::string> choices);
  static Key point(std::string name, std::string doc, std::string unit = "");  // [x, y]
  static Key reals(std::string name, std::string doc, std::string unit = "");  // [a, b, ...]
  // A nested section; absent sections stay absent (the part they describe is not built) unless `always`.
  static Key section(std::string name, std::string doc, std::shared_ptr<const Schema> schema);
  // A list of sections of one schema; absent lists resolve to [].
  static Key list(std::string name, std::string doc, std::shared_ptr<const Schema> item);

  Key& required();
  Key& always();  // a section that is resolved from its defaults even when absent
  // A section resolved from its defaults when absent but every one of `siblings` is present (e.g. the coupling
  // of water and plate when the scene has both).
  Key& implied_by(std::vector<std::string> siblings);
  Key& def(double v);
  Key& def(int v);
  Key& def(bool v);
  Key& def(const char* v);
  Key& def(const std::string& v);
  Key& def_point(double x, double y);
  Key& def_yaml(const std::string& yaml_text);  // any default, as YAML text
  Key& positive();                              // > 0
  Key& non_negative();                          // >= 0
  Key& at_least(double lo);                     // >= lo
  Key& above(double lo);                        // > lo
  Key& at_most(double hi);                      // <= hi
  Key& below(double hi);                        // < hi
  Key& in(double lo, double hi);                // lo <= v <= hi
  Key& min_items(int n);                        // reals, list

  const std::string& name() const { return name_; }
  const std::string& doc() const { return doc_; }
  const std::string& unit() const { return unit_; }
  ValueKind kind() const { return kind_; }
  bool is_required() const { return required_; }
  bool is_always() const { return always_; }
  const std::vector<std::string>& implying_siblings() const { return implied_by_; }
  const std::optional<std::string>& default_yaml() const { return default_; }
  const std::vector<std::string>& choices() const { return choices_; }
  const std::shared_ptr<const Schema>& schema() const { return schema_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  bool lo_open() const { return lo_open_; }
  bool hi_open() const { return hi_open_; }
  int min_items_count() const { return min_items_; }
  // "a number > 0 (m)", "one of delta, standard", ...: what the key expects, for messages and the reference.
  std::string expectation() const;

 private:
  Key(std::string name, std::string doc, ValueKind kind)
      : name_(std::move(name)), doc_(std::move(doc)), kind_(kind) {}
  std::string name_, doc_, unit_;
  ValueKind kind_;
  bool required_ = false, always_ = false;
  std::optional<std::string> default_;
  std::vector<std::string> choices_;
  std::vector<std::string> implied_by_;
  std::shared_ptr<const Schema> schema_;
  double lo_ = -std::numeric_limits<double>::infinity(), hi_ = std::numeric_limits<double>::infinity();
  bool lo_open_ = false, hi_open_ = false;
  int min_items_ = 0;
};

// The keys of one section, in the order they are written back. A section may be split into variants by one
// choice key (the discriminator, e.g. `kind`): each variant adds keys of its own.
class Schema {
 public:
  explicit Schema(std::string doc = "") : doc_(std::move(doc)) {}
  Schema& add(Key key);
  // Declares `key` (already added as a choice key) the discriminator; variants are added with `variant`.
  Schema& discriminator(const std::string& key);
  Schema& variant(const std::string& value, std::shared_ptr<const Schema> extra);

  const std::string& doc() const { return doc_; }
  const std::vector<Key>& keys() const { return keys_; }
  const Key* find(const std::string& name) const;
  const std::string& discriminator_key() const { return discriminator_; }
  const std::map<std::string, std::shared_ptr<const Schema>>& variants() const { return variants_; }

 private:
  std::string doc_;
  std::vector<Key> keys_;
  std::string discriminator_;
  std::map<std::string, std::shared_ptr<const Schema>> variants_;
};

// Where a raw tree came from, for messages: the file, and the key paths that --set overrode.
struct Origin {
  std::string file;
  std::map<std::string, std::string> overrides;  // "fluid.spacing" -> "0.002"
};

// Checks `raw` against `schema` and returns the resolved tree (schema order, defaults filled).
YAML::Node resolve(const YAML::Node& raw, const Schema& schema, const Origin& origin);

// Applies `--set path=value` to a raw tree (maps are created on the way; list items by index). Throws UserError
// for a malformed assignment.
void apply_override(YAML::Node& raw, const std::string& assignment, Origin& origin);

// The closest name to `word` among `candidates` when it is a near miss (edit distance small), else "".
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);

// Markdown reference of a schema (one table per section), for docs/scene-reference.md.
std::string reference_markdown(const Schema& schema, const std::string& title);

}  // namespace halfeti::scene
