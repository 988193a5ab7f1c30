// Reading YAML files (configurations, scenarios) with one-line errors that name the file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>

namespace colav {

/// Parses the YAML file at `path`. A missing, unreadable or malformed file, or a key given twice
/// in one map, is a colav::UserError naming the file (and the line).
YAML::Node LoadYamlFile(const std::filesystem::path& path);

}  // namespace colav
