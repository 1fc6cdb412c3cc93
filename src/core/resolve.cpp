// Checking a raw scene tree against its schema (schema.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "halfeti/core/error.hpp"
#include "halfeti/core/schema.hpp"

namespace halfeti::scene {

namespace {

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string scalar_text(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a section";
  return "an unreadable value";
}

// A scene's errors are all reported in one pass (up to kMaxReported): fail() records one and unwinds, by a
// Recorded, to the key or list item that holds the bad value; the resolver goes on with the next.
constexpr std::size_t kMaxReported = 20;
struct Recorded {};

class Resolver {
 public:
  explicit Resolver(const Origin& origin) : origin_(origin) {}

  // Throws UserError with every recorded error, one per line in the order of the scene's text (the --set
  // overrides first), when there is any.
  void raise_if_any() {
    if (errors_.empty()) return;
    std::stable_sort(errors_.begin(), errors_.end(), [](const Entry& a, const Entry& b) {
      return std::tie(a.line, a.column) < std::tie(b.line, b.column);
    });
    std::string text;
    const std::size_t shown = std::min(errors_.size(), kMaxReported);
    for (std::size_t i = 0; i < shown; ++i) text += (i ? "\n" : "") + errors_[i].text;
    if (errors_.size() > shown)
      text += "\n" + file() + ": " + std::to_string(errors_.size() - shown) + " more errors not shown (" +
              std::to_string(errors_.size()) + " in all)";
    throw UserError(text);
  }

  YAML::Node section(const YAML::Node& raw, const Schema& schema, const std::string& path,
                     const YAML::Node& at) {
    if (raw.IsDefined() && !raw.IsNull() && !raw.IsMap())
      fail(raw, path, "expected a section (key: value lines), found " + scalar_text(raw));
    const YAML::Node in = (raw.IsDefined() && raw.IsMap()) ? raw : YAML::Node(YAML::NodeType::Map);
    const YAML::Node& located = (raw.IsDefined() && !raw.IsNull()) ? raw : at;

    std::vector<const Key*> keys;
    for (const auto& k : schema.keys()) keys.push_back(&k);
    const Schema* variant = nullptr;
    std::string variant_name;
    if (!schema.discriminator_key().empty()) {
      const Key* dk = schema.find(schema.discriminator_key());
      const YAML::Node d = in[dk->name()];
      YAML::Node resolved_d;
      if (d.IsDefined())
        resolved_d = value(d, *dk, join_path(path, dk->name()));
      else if (dk->default_yaml())
        resolved_d = YAML::Node(*dk->default_yaml());
      else
        fail(located, join_path(path, dk->name()), "required key missing: expected " + dk->expectation());
      variant_name = resolved_d.Scalar();
      auto it = schema.variants().find(variant_name);
      if (it != schema.variants().end()) {
        variant = it->second.get();
        for (const auto& k : variant->keys()) keys.push_back(&k);
      }
    }

    std::vector<std::string> meant;  // keys a near-miss spelling stood for: not reported missing as well
    std::vector<std::string> names;
    for (const Key* k : keys) names.push_back(k->name());
    auto is_known = [&](const std::string& name) {
      return std::any_of(keys.begin(), keys.end(), [&](const Key* k) { return k->name() == name; });
    };
    // A misspelt discriminator (kind) leaves its default variant in force, under which the variant's own keys are
    // unknown too: only the misspelling is reported, the rest follows from it.
    bool discriminator_misspelt = false;
    const std::string& dkey = schema.discriminator_key();
    if (!dkey.empty() && !in[dkey].IsDefined())
      for (auto it = in.begin(); it != in.end(); ++it)
        if (!is_known(it->first.Scalar()) && closest_name(it->first.Scalar(), names) == dkey)
          discriminator_misspelt = true;
    for (auto it = in.begin(); it != in.end(); ++it) {
      const std::string name = it->first.Scalar();
      if (is_known(name)) continue;
      const std::string near = closest_name(name, names);
      if (discriminator_misspelt && near != dkey) continue;
      std::string msg = "unknown key '" + join_path(path, name) + "'";
      if (!variant_name.empty()) msg += " for " + schema.discriminator_key() + " '" + variant_name + "'";
      if (!near.empty()) {
        msg += "; did you mean '" + near + "'?";
        meant.push_back(near);
      } else {
        msg += "; expected one of: ";
        for (size_t i = 0; i < names.size(); ++i) msg += (i ? ", " : "") + names[i];
      }
      record(it->first, join_path(path, name), msg);
    }

    YAML::Node out(YAML::NodeType::Map);
    for (const Key* k : keys) {
      if (std::find(meant.begin(), meant.end(), k->name()) != meant.end() && !in[k->name()].IsDefined())
        continue;
      try {
        resolve_key(in, *k, path, located, out);
      } catch (const Recorded&) {  // recorded; on to the next key
      }
    }
    return out;
  }

  // One key of a section into `out`: its value, its default, or the section it implies.
  void resolve_key(const YAML::Node& in, const Key& k, const std::string& path, const YAML::Node& located,
                   YAML::Node& out) {
    const std::string kp = join_path(path, k.name());
    const YAML::Node v = in[k.name()];
    if (v.IsDefined() && !(v.IsNull() && k.kind() == ValueKind::kSection)) {
      out[k.name()] = value(v, k, kp);
    } else if (v.IsDefined() && v.IsNull()) {
      out[k.name()] = section(YAML::Node(YAML::NodeType::Map), *k.schema(), kp, v);
    } else if (k.default_yaml()) {
      out[k.name()] = value(YAML::Load(*k.default_yaml()), k, kp);
    } else if (k.is_required()) {
      fail(located, kp, "required key missing: expected " + k.expectation());
    } else if (k.kind() == ValueKind::kSection && (k.is_always() || implied(k, in))) {
      out[k.name()] = section(YAML::Node(YAML::NodeType::Map), *k.schema(), kp, located);
    } else if (k.kind() == ValueKind::kList) {
      out[k.name()] = YAML::Node(YAML::NodeType::Sequence);
    }
  }

  YAML::Node value(const YAML::Node& v, const Key& key, const std::string& path) {
    const auto expected = [&]() { return "expected " + key.expectation() + ", found " + scalar_text(v); };
    switch (key.kind()) {
      case ValueKind::kReal: {
        const double x = number(v, key, path);
        check_range(v, key, path, x);
        return YAML::Node(v.Scalar());
      }
      case ValueKind::kInteger: {
        long long n = 0;
        if (!v.IsScalar() || !YAML::convert<long long>::decode(v, n)) fail(v, path, expected());
        check_range(v, key, path, static_cast<double>(n));
        return YAML::Node(std::to_string(n));
      }
      case ValueKind::kBool: {
        bool b = false;
        if (!v.IsScalar() || !YAML::convert<bool>::decode(v, b)) fail(v, path, expected());
        return YAML::Node(b ? "true" : "false");
      }
      case ValueKind::kString:
        if (!v.IsScalar() || v.Scalar().empty()) fail(v, path, expected());
        return YAML::Node(v.Scalar());
      case ValueKind::kChoice: {
        if (!v.IsScalar()) fail(v, path, expected());
        const auto& c = key.choices();
        if (std::find(c.begin(), c.end(), v.Scalar()) == c.end()) {
          std::string msg = expected();
          const std::string near = closest_name(v.Scalar(), c);
          if (!near.empty()) msg += "; did you mean '" + near + "'?";
          fail(v, path, msg);
        }
        return YAML::Node(v.Scalar());
      }
      case ValueKind::kPoint: {
        if (!v.IsSequence() || v.size() != 2) fail(v, path, expected());
        YAML::Node out(YAML::NodeType::Sequence);
        out.SetStyle(YAML::EmitterStyle::Flow);
        for (size_t i = 0; i < 2; ++i) {
          number(v[i], key, path + "[" + std::to_string(i) + "]");
          out.push_back(v[i].Scalar());
        }
        return out;
      }
      case ValueKind::kRealList: {
        if (!v.IsSequence()) fail(v, path, expected());
        if (static_cast<int>(v.size()) < key.min_items_count())
          fail(v, path,
               "expected at least " + std::to_string(key.min_items_count()) + " numbers, found " +
                   std::to_string(v.size()));
        YAML::Node out(YAML::NodeType::Sequence);
        out.SetStyle(YAML::EmitterStyle::Flow);
        for (size_t i = 0; i < v.size(); ++i) {
          const std::string ip = path + "[" + std::to_string(i) + "]";
          check_range(v[i], key, ip, number(v[i], key, ip));
          out.push_back(v[i].Scalar());
        }
        return out;
      }
      case ValueKind::kSection:
        return section(v, *key.schema(), path, v);
      case ValueKind::kList: {
        if (!v.IsSequence()) fail(v, path, expected());
        if (static_cast<int>(v.size()) < key.min_items_count())
          fail(v, path,
               "expected at least " + std::to_string(key.min_items_count()) + " items, found " +
                   std::to_string(v.size()));
        YAML::Node out(YAML::NodeType::Sequence);
        bool complete = true;
        for (size_t i = 0; i < v.size(); ++i) {
          try {  // every item is checked, whatever the one before held
            out.push_back(section(v[i], *key.schema(), path + "[" + std::to_string(i) + "]", v[i]));
          } catch (const Recorded&) {
            complete = false;
          }
        }
        if (!complete) throw Recorded{};
        return out;
      }
    }
    fail(v, path, expected());
  }

 private:
  static bool implied(const Key& key, const YAML::Node& in) {
    const auto& siblings = key.implying_siblings();
    if (siblings.empty()) return false;
    for (const auto& s : siblings)
      if (!in[s].IsDefined() || in[s].IsNull()) return false;
    return true;
  }

  double number(const YAML::Node& v, const Key& key, const std::string& path) {
    double x = 0;
    if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x))
      fail(v, path, "expected " + key.expectation() + ", found " + scalar_text(v));
    return x;
  }

  void check_range(const YAML::Node& v, const Key& key, const std::string& path, double x) {
    const bool low = key.lo_open() ? !(x > key.lo()) : !(x >= key.lo());
    const bool high = key.hi_open() ? !(x < key.hi()) : !(x <= key.hi());
    if (low || high) fail(v, path, "expected " + key.expectation() + ", found " + scalar_text(v));
  }

  // The --set override that set `path` (or a section above it), or null.
  const std::pair<const std::string, std::string>* override_for(const std::string& path) const {
    for (const auto& o : origin_.overrides) {
      const std::string& opath = o.first;
      if (path == opath || path.rfind(opath + ".", 0) == 0 || path.rfind(opath + "[", 0) == 0) return &o;
    }
    return nullptr;
  }

  // Records one error: "<file>:<line>:<column>: <key path>: <what>" (or "--set key=value: ..."), with its place
  // for the order of the report (the overrides first, then by line and column, then those without a place).
  void record(const YAML::Node& node, const std::string& path, const std::string& msg) {
    const std::string what = msg.rfind("unknown key", 0) == 0 ? msg : path + ": " + msg;
    Entry e;
    if (const auto* o = override_for(path)) {
      e.text = "--set " + o->first + "=" + o->second + ": " + what;
    } else if (node.IsDefined() && !node.Mark().is_null()) {
      e.line = node.Mark().line + 1;
      e.column = node.Mark().column + 1;
      e.text = file() + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " + what;
    } else {
      e.line = std::numeric_limits<int>::max();
      e.text = file() + ": " + what;
    }
    errors_.push_back(std::move(e));
  }

  std::string file() const { return origin_.file.empty() ? "<scene>" : origin_.file; }

  // Records one error and unwinds to the key that holds the value.
  [[noreturn]] void fail(const YAML::Node& node, const std::string& path, const std::string& msg) {
    record(node, path, msg);
    throw Recorded{};
  }

  struct Entry {
    int line = 0, column = 0;  // 0: a --set override (reported first)
    std::string text;
  };
  const Origin& origin_;
  std::vector<Entry> errors_;
};

}  // namespace

YAML::Node resolve(const YAML::Node& raw, const Schema& schema, const Origin& origin) {
  Resolver r(origin);
  YAML::Node out;
  try {
    out = r.section(raw, schema, "", raw);
  } catch (const Recorded&) {  // the whole tree was not a section: recorded
  }
  r.raise_if_any();
  return out;
}

void apply_override(YAML::Node& raw, const std::string& assignment, Origin& origin) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == assignment.size())
    HALFETI_USER_ERROR("--set " << assignment << ": expected key.path=value, e.g. --set fluid.spacing=0.002");
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    HALFETI_USER_ERROR("--set " << assignment << ": the value is not valid YAML (" << e.msg << ")");
  }
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) {
    if (p.empty())
      HALFETI_USER_ERROR("--set " << assignment << ": empty component in key path '" << path << "'");
    parts.push_back(p);
  }
  if (!raw.IsDefined() || raw.IsNull()) raw = YAML::Node(YAML::NodeType::Map);
  // yaml-cpp nodes are handles: walking with operator= would rebind, so keep the chain and assign at the end.
  std::vector<YAML::Node> chain{raw};
  std::string display;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node cur = chain.back();
    const std::string& p = parts[i];
    display = display.empty() ? p : display + "." + p;
    if (cur.IsSequence()) {
      size_t idx = 0;
      try {
        idx = std::stoul(p);
      } catch (...) {
        HALFETI_USER_ERROR("--set " << assignment << ": '" << display << "' is a list; use an index, e.g. "
                                    << display.substr(0, display.size() - p.size()) << "0");
      }
      if (idx >= cur.size())
        HALFETI_USER_ERROR("--set " << assignment << ": list index " << idx << " out of range (the list has "
                                    << cur.size() << " items)");
      chain.push_back(cur[idx]);
    } else {
      if (cur.IsScalar())
        HALFETI_USER_ERROR("--set " << assignment << ": '" << display << "' holds a value, not a section");
      YAML::Node next = cur[p];
      if (!next.IsDefined() || next.IsNull()) {
        cur[p] = YAML::Node(YAML::NodeType::Map);
        next = cur[p];
      }
      chain.push_back(next);
    }
  }
  YAML::Node last = chain.back();
  if (last.IsSequence()) {
    size_t idx = 0;
    try {
      idx = std::stoul(parts.back());
    } catch (...) {
      HALFETI_USER_ERROR("--set " << assignment << ": '" << path << "' indexes a list with a non-number");
    }
    if (idx >= last.size())
      HALFETI_USER_ERROR("--set " << assignment << ": list index " << idx << " out of range");
    last[idx] = value;
  } else {
    if (last.IsScalar())
      HALFETI_USER_ERROR("--set " << assignment << ": '" << display << "' holds a value, not a section");
    last[parts.back()] = value;
  }
  // Messages name the override with the path as the resolver spells it (list items as name[i]).
  std::string canonical;
  for (const auto& p : parts) {
    const bool index = !p.empty() && std::all_of(p.begin(), p.end(), ::isdigit);
    canonical = canonical.empty() ? p : (index ? canonical + "[" + p + "]" : canonical + "." + p);
  }
  origin.overrides[canonical] = text;
}

}  // namespace halfeti::scene
