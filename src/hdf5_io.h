// Small helpers over the HDF5 C++ API for the project's datasets: float matrices and vectors,
// integer vectors and scalar attributes on the file, with one-line colav::UserError messages
// naming the file and the dataset. Files are read whole; they are tens of megabytes at most.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace H5 {
class H5File;
}  // namespace H5

namespace colav {

/// A row-major matrix read from a dataset.
struct FloatMatrix {
  std::vector<float> data;
  std::size_t rows = 0;
  std::size_t cols = 0;
};

/// An open HDF5 file. Dataset names may contain groups ("/a/b"); writing creates the groups.
/// Not thread-safe (neither is the HDF5 library as Debian builds it).
class Hdf5File {
 public:
  /// Opens an existing file for reading.
  static Hdf5File Open(const std::filesystem::path& path);
  /// Creates `path` through WriteFileAtomically: `write` fills the new file, which replaces `path`
  /// only once complete.
  static void CreateAtomically(const std::filesystem::path& path,
                               const std::function<void(Hdf5File& file)>& write);

  Hdf5File(Hdf5File&& other) noexcept;
  Hdf5File& operator=(Hdf5File&& other) noexcept;
  ~Hdf5File();

  const std::filesystem::path& path() const { return path_; }
  bool HasDataset(const std::string& name) const;

  /// `data` holds rows * cols values, row-major.
  void WriteFloatMatrix(const std::string& name, const std::vector<float>& data, std::size_t rows,
                        std::size_t cols);
  void WriteFloatVector(const std::string& name, const std::vector<float>& data);
  void WriteIntVector(const std::string& name, const std::vector<std::int64_t>& data);

  /// A 2-D float dataset; expected_cols = -1 accepts any number of columns.
  FloatMatrix ReadFloatMatrix(const std::string& name, std::int64_t expected_cols = -1) const;
  std::vector<float> ReadFloatVector(const std::string& name) const;
  std::vector<std::int64_t> ReadIntVector(const std::string& name) const;

  // Scalar attributes of the file (setting one replaces an attribute of the same name).
  bool HasAttribute(const std::string& name) const;
  void SetAttribute(const std::string& name, const std::string& value);
  void SetAttribute(const std::string& name, const char* value) {
    SetAttribute(name, std::string(value));
  }
  void SetAttribute(const std::string& name, double value);
  void SetAttribute(const std::string& name, std::int64_t value);
  /// Any other integer type (int, std::uint64_t seeds, ...); std::out_of_range beyond int64.
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
  void SetAttribute(const std::string& name, Integer value) {
    SetAttribute(name, CheckedInt64(value));
  }
  std::string GetStringAttribute(const std::string& name) const;
  double GetDoubleAttribute(const std::string& name) const;
  std::int64_t GetIntAttribute(const std::string& name) const;

 private:
  Hdf5File(std::unique_ptr<H5::H5File> file, std::filesystem::path path);
  void Close();

  template <typename Integer>
  static std::int64_t CheckedInt64(Integer value) {
    if constexpr (std::is_unsigned_v<Integer> && sizeof(Integer) >= sizeof(std::int64_t)) {
      if (value > static_cast<Integer>(std::numeric_limits<std::int64_t>::max())) {
        throw std::out_of_range("Hdf5File: attribute value exceeds int64");
      }
    }
    return static_cast<std::int64_t>(value);
  }

  std::unique_ptr<H5::H5File> file_;
  std::filesystem::path path_;  // the destination path, for messages
};

}  // namespace colav
