// The scene reference page, generated from the schema so that it cannot drift from what the code accepts.
#include <sstream>

#include "halfeti/core/schema.hpp"

namespace halfeti::scene {

namespace {

void write_section(std::ostringstream& os, const Schema& schema, const std::string& path,
                   const std::string& note) {
  os << "\n### `" << (path.empty() ? "(top level)" : path) << "`" << note << "\n\n";
  if (!schema.doc().empty()) os << schema.doc() << "\n\n";
  os << "| key | expects | default | meaning |\n|---|---|---|---|\n";
  for (const auto& k : schema.keys()) {
    std::string def = k.default_yaml() ? "`" + *k.default_yaml() + "`" : (k.is_required() ? "required" : "—");
    if (!k.implying_siblings().empty()) {
      def = "defaults with";
      for (const auto& s : k.implying_siblings()) def += " `" + s + "`";
    }
    os << "| `" << k.name() << "` | " << k.expectation() << " | " << def << " | " << k.doc() << " |\n";
  }
  for (const auto& k : schema.keys()) {
    const std::string sub = path.empty() ? k.name() : path + "." + k.name();
    if (k.kind() == ValueKind::kSection) write_section(os, *k.schema(), sub, "");
    if (k.kind() == ValueKind::kList) write_section(os, *k.schema(), sub + "[]", " (each item)");
  }
  for (const auto& [name, v] : schema.variants())
    if (!v->keys().empty())
      write_section(os, *v, path, " with `" + schema.discriminator_key() + ": " + name + "`");
}

}  // namespace

std::string reference_markdown(const Schema& schema, const std::string& title) {
  std::ostringstream os;
  os << "# " << title << "\n";
  write_section(os, schema, "", "");
  return os.str();
}

}  // namespace halfeti::scene
