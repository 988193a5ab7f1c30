#include "src/csv_table.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

#include "src/error.h"
#include "src/number_text.h"

namespace colav {
namespace {

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// Header is line 1, row k is line k + 2.
std::string Where(const CsvTable& table, std::size_t row) {
  return table.path.string() + ":" + std::to_string(row + 2);
}

// The error of a numeric column's field that is not a number (built outside the row loop).
UserError NotANumber(const CsvTable& table, std::size_t row, const std::string& column,
                     const std::string& field) {
  return UserError(Where(table, row) + ": column '" + column + "': '" + field +
                   "' is not a finite number");
}

}  // namespace

CsvTable ReadCsvTable(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw UserError(path.string() + ": cannot read the CSV file");
  const std::string content((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
  std::istringstream lines(content);
  CsvTable table{path, {}, {}};
  std::string line;
  if (!std::getline(lines, line) || line.empty()) {
    throw UserError(path.string() + ": empty CSV file (no header)");
  }
  table.header = SplitFields(line);
  const bool last_line_complete = content.back() == '\n';
  while (std::getline(lines, line)) {
    if (lines.eof() && !last_line_complete) break;
    std::vector<std::string> fields = SplitFields(line);
    if (fields.size() != table.header.size()) {
      throw UserError(Where(table, table.rows.size()) + ": " + std::to_string(fields.size()) +
                      " fields, the header has " + std::to_string(table.header.size()));
    }
    table.rows.push_back(std::move(fields));
  }
  return table;
}

std::vector<double> NumericColumn(const CsvTable& table, const std::string& name) {
  const auto column = std::find(table.header.begin(), table.header.end(), name);
  if (column == table.header.end()) {
    throw UserError(table.path.string() + ": no column '" + name + "'");
  }
  const std::size_t index = static_cast<std::size_t>(column - table.header.begin());
  std::vector<double> values;
  values.reserve(table.rows.size());
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string& field = table.rows[r][index];
    const std::optional<double> value = ParseFiniteNumber(field);
    if (!value) throw NotANumber(table, r, name, field);
    values.push_back(*value);
  }
  return values;
}

}  // namespace colav
