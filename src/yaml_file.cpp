#include "src/yaml_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "src/error.h"

namespace colav {

YAML::Node LoadYamlFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) throw UserError(name + ": no such file");
  if (std::filesystem::is_directory(path)) throw UserError(name + ": is a folder, not a file");
  std::ifstream file(path);
  if (!file) throw UserError(name + ": cannot read (" + std::strerror(errno) + ")");
  std::stringstream text;
  text << file.rdbuf();
  try {
    return YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    // yaml-cpp's marks count from 0; editors count from 1.
    throw UserError(name + ": malformed YAML at line " + std::to_string(e.mark.line + 1) +
                    ", column " + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

}  // namespace colav
