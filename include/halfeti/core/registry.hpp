// One registry per kind of named choice (excitation, probe, kernel, material ...): a name maps to the schema of
// its own keys and to a factory. Adding a choice is one `add` call; the scene schema's choice list and variants
// are built from the registry, so the two cannot disagree.
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "halfeti/core/error.hpp"
#include "halfeti/core/schema.hpp"

namespace halfeti {

template <class Factory>
class Registry {
 public:
  struct Entry {
    std::string doc;
    std::shared_ptr<const scene::Schema> keys;  // the keys this choice adds to its section
    Factory make;
  };

  Registry& add(const std::string& name, std::string doc, std::shared_ptr<const scene::Schema> keys,
                Factory make) {
    HALFETI_CHECK(entries_.find(name) == entries_.end(), "registry entry '" << name << "' added twice");
    names_.push_back(name);
    entries_[name] = Entry{std::move(doc), std::move(keys), std::move(make)};
    return *this;
  }
  const Entry& get(const std::string& name) const {
    auto it = entries_.find(name);
    HALFETI_CHECK(it != entries_.end(), "no registry entry '" << name << "'");
    return it->second;
  }
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  // Names in the order they were added.
  const std::vector<std::string>& names() const { return names_; }

  // A section schema whose `discriminator` key picks one entry and admits that entry's keys. `common` keys
  // (e.g. a probe's name) come first.
  std::shared_ptr<scene::Schema> section_schema(const std::string& discriminator, const std::string& doc,
                                                const std::vector<scene::Key>& common = {},
                                                const std::string& default_choice = "") const {
    auto s = std::make_shared<scene::Schema>(doc);
    for (const auto& k : common) s->add(k);
    std::string choice_doc = "which kind; each adds the keys of its own table below";
    auto key = scene::Key::choice(discriminator, choice_doc, names_);
    if (default_choice.empty())
      key.required();
    else
      key.def(default_choice);
    s->add(key);
    s->discriminator(discriminator);
    for (const auto& n : names_) s->variant(n, entries_.at(n).keys);
    return s;
  }

 private:
  std::vector<std::string> names_;
  std::map<std::string, Entry> entries_;
};

// A registry of plain named values (kernel, scheme, material ...): each entry's "factory" is the value itself.
template <class T>
Registry<T> named_values(std::initializer_list<std::tuple<const char*, const char*, T>> entries) {
  Registry<T> r;
  for (const auto& [name, doc, value] : entries) r.add(name, doc, nullptr, value);
  return r;
}

}  // namespace halfeti
