// Reading the CSV logs the figures are drawn from (train_ppo's episodes.csv): a header line, then
// rows of plain comma-separated fields (no quoting: the project's CSV writers never need it).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace colav {

struct CsvTable {
  std::filesystem::path path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// Reads `path`. A missing file, an empty file or a row whose field count differs from the
/// header's is a UserError naming the file (and line). A last line without its newline is a row
/// still being written by a running program, and is left out.
CsvTable ReadCsvTable(const std::filesystem::path& path);

/// The values of column `name`; UserError naming the file and column when it is absent, or the
/// file, line and column when a field is not a finite number (NaN and infinities included).
std::vector<double> NumericColumn(const CsvTable& table, const std::string& name);

}  // namespace colav
