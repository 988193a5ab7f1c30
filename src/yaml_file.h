// Reading YAML files (configurations, scenarios) with one-line errors that name the file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>

namespace colav {

/// Parses the YAML file at `path`. A missing, unreadable or malformed file is a colav::UserError
/// naming the file (and, for malformed YAML, the line and column).
YAML::Node LoadYamlFile(const std::filesystem::path& path);

}  // namespace colav
