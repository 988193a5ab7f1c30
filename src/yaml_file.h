// Reading YAML files (configurations, scenarios) with one-line errors that name the file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

namespace colav {

/// Parses the YAML file at `path`. A missing, unreadable or malformed file, or a key given twice
/// in one map, is a colav::UserError naming the file (and the line).
YAML::Node LoadYamlFile(const std::filesystem::path& path);
/// Parses YAML `text` read from `origin` (a file, or a record inside one), with LoadYamlFile's
/// errors naming `origin`.
YAML::Node ParseYamlText(const std::string& text, const std::string& origin);

}  // namespace colav
