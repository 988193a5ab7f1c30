#include "src/yaml_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "src/error.h"

namespace colav {
namespace {

// yaml-cpp keeps both entries of a key given twice in one map, and readers would silently take
// one of them: a duplicate is an error naming the file, the line and the key.
void RejectDuplicateKeys(const YAML::Node& node, const std::string& name) {
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) RejectDuplicateKeys(item, name);
  }
  if (!node.IsMap()) return;
  std::set<std::string> keys;
  for (const auto& item : node) {
    if (item.first.IsScalar() && !keys.insert(item.first.Scalar()).second) {
      throw UserError(name + ": line " + std::to_string(item.first.Mark().line + 1) +
                      ": duplicate key '" + item.first.Scalar() + "'");
    }
    RejectDuplicateKeys(item.second, name);
  }
}

}  // namespace

YAML::Node LoadYamlFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) throw UserError(name + ": no such file");
  if (std::filesystem::is_directory(path)) throw UserError(name + ": is a folder, not a file");
  std::ifstream file(path);
  if (!file) throw UserError(name + ": cannot read (" + std::strerror(errno) + ")");
  std::stringstream text;
  text << file.rdbuf();
  return ParseYamlText(text.str(), name);
}

YAML::Node ParseYamlText(const std::string& text, const std::string& origin) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    // yaml-cpp's marks count from 0; editors count from 1.
    throw UserError(origin + ": malformed YAML at line " + std::to_string(e.mark.line + 1) +
                    ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  RejectDuplicateKeys(root, origin);
  return root;
}

}  // namespace colav
