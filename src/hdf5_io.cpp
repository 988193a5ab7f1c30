#include "src/hdf5_io.h"

#include <H5Cpp.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <utility>

#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

// HDF5 prints its whole error stack to stderr by default; our messages say what went wrong.
void SilenceHdf5Errors() {
  static const bool silenced = [] {
    H5::Exception::dontPrint();
    return true;
  }();
  (void)silenced;
}

// Runs an HDF5 call, turning its exceptions (which are not std::exceptions) into a UserError.
template <typename Function>
auto Guarded(const std::filesystem::path& path, const std::string& action, Function function) {
  try {
    return function();
  } catch (const H5::Exception& e) {
    throw UserError(path.string() + ": cannot " + action + " (HDF5: " + e.getDetailMsg() + ")");
  }
}

std::vector<hsize_t> DatasetDims(const H5::DataSet& dataset) {
  const H5::DataSpace space = dataset.getSpace();
  std::vector<hsize_t> dims(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(dims.data());
  return dims;
}

const char* ClassName(H5T_class_t type_class) {
  switch (type_class) {
    case H5T_FLOAT:
      return "floating-point";
    case H5T_INTEGER:
      return "integer";
    case H5T_STRING:
      return "string";
    default:
      return "non-numeric";
  }
}

void WriteDataset(H5::H5File& file, const std::filesystem::path& path, const std::string& name,
                  const void* data, const H5::PredType& file_type, const H5::PredType& memory_type,
                  const std::vector<hsize_t>& dims) {
  Guarded(path, "write dataset '" + name + "'", [&] {
    H5::LinkCreatPropList links;
    links.setCreateIntermediateGroup(true);
    const H5::DataSpace space(static_cast<int>(dims.size()), dims.data());
    H5::DataSet dataset = file.createDataSet(name, file_type, space, H5::DSetCreatPropList::DEFAULT,
                                             H5::DSetAccPropList::DEFAULT, links);
    dataset.write(data, memory_type);
  });
}

// The values of dataset `name`, checked to be of `type_class` and of rank dims.size(); fills dims.
template <typename T>
std::vector<T> ReadDataset(const Hdf5File& owner, const H5::H5File& file, const std::string& name,
                           H5T_class_t type_class, const H5::PredType& memory_type,
                           std::vector<hsize_t>& dims) {
  const std::string where = owner.path().string() + ": dataset '" + name + "' ";
  if (!owner.HasDataset(name)) {
    throw UserError(owner.path().string() + ": no dataset '" + name + "'");
  }
  return Guarded(owner.path(), "read dataset '" + name + "'", [&] {
    const H5::DataSet dataset = file.openDataSet(name);
    const H5T_class_t actual_class = dataset.getTypeClass();
    if (actual_class != type_class) {
      throw UserError(where + "holds " + ClassName(actual_class) + " values, expected " +
                      ClassName(type_class));
    }
    const std::vector<hsize_t> actual_dims = DatasetDims(dataset);
    if (actual_dims.size() != dims.size()) {
      throw UserError(where + "has " + std::to_string(actual_dims.size()) +
                      " dimensions, expected " + std::to_string(dims.size()));
    }
    dims = actual_dims;
    std::size_t count = 1;
    for (const hsize_t dim : dims) count *= dim;
    std::vector<T> values(count);
    if (count > 0) dataset.read(values.data(), memory_type);
    return values;
  });
}

void WriteAttribute(H5::H5File& file, const std::filesystem::path& path, const std::string& name,
                    const H5::DataType& file_type,
                    const std::function<void(H5::Attribute&)>& write) {
  Guarded(path, "write attribute '" + name + "'", [&] {
    if (file.attrExists(name)) file.removeAttr(name);
    H5::Attribute attribute = file.createAttribute(name, file_type, H5::DataSpace(H5S_SCALAR));
    write(attribute);
  });
}

// Variable-length UTF-8, which h5py reads as str.
H5::StrType Utf8StringType() {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

// Reads scalar attribute `name`, checked to be of `type_class`, with `read`.
template <typename T>
T ReadAttribute(const Hdf5File& owner, const H5::H5File& file, const std::string& name,
                H5T_class_t type_class, const std::function<void(const H5::Attribute&, T&)>& read) {
  const std::string where = owner.path().string() + ": attribute '" + name + "' ";
  if (!owner.HasAttribute(name)) {
    throw UserError(owner.path().string() + ": no attribute '" + name + "'");
  }
  return Guarded(owner.path(), "read attribute '" + name + "'", [&] {
    const H5::Attribute attribute = file.openAttribute(name);
    const H5T_class_t actual_class = attribute.getTypeClass();
    if (actual_class != type_class) {
      throw UserError(where + "is " + ClassName(actual_class) + ", expected " +
                      ClassName(type_class));
    }
    T value{};
    read(attribute, value);
    return value;
  });
}

}  // namespace

Hdf5File::Hdf5File(std::unique_ptr<H5::H5File> file, std::filesystem::path path)
    : file_(std::move(file)), path_(std::move(path)) {}
Hdf5File::Hdf5File(Hdf5File&& other) noexcept = default;
Hdf5File& Hdf5File::operator=(Hdf5File&& other) noexcept = default;
Hdf5File::~Hdf5File() = default;

Hdf5File Hdf5File::Open(const std::filesystem::path& path) {
  SilenceHdf5Errors();
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) throw UserError(name + ": no such file");
  if (!std::ifstream(path)) throw UserError(name + ": cannot read (" + std::strerror(errno) + ")");
  try {
    return Hdf5File(std::make_unique<H5::H5File>(name, H5F_ACC_RDONLY), path);
  } catch (const H5::Exception&) {
    throw UserError(name + ": not an HDF5 file, or damaged or truncated");
  }
}

void Hdf5File::CreateAtomically(const std::filesystem::path& path,
                                const std::function<void(Hdf5File&)>& write) {
  SilenceHdf5Errors();
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5File file(
        Guarded(path, "create file",
                [&] { return std::make_unique<H5::H5File>(temporary.string(), H5F_ACC_TRUNC); }),
        path);
    write(file);
    file.Close();  // flushes everything before WriteFileAtomically syncs and renames
  });
}

void Hdf5File::Close() {
  Guarded(path_, "write", [&] { file_->close(); });
}

bool Hdf5File::HasDataset(const std::string& name) const {
  return Guarded(path_, "read", [&] {
    // H5Lexists fails on a path whose groups are missing, so walk it one link at a time.
    std::size_t end = name.find_first_not_of('/');
    while (end != std::string::npos) {
      end = name.find('/', end);
      if (!file_->nameExists(name.substr(0, end))) return false;
      if (end != std::string::npos) ++end;
    }
    return file_->childObjType(name) == H5O_TYPE_DATASET;
  });
}

void Hdf5File::WriteFloatMatrix(const std::string& name, const std::vector<float>& data,
                                std::size_t rows, std::size_t cols) {
  if (data.size() != rows * cols) {
    throw std::invalid_argument("WriteFloatMatrix: " + std::to_string(data.size()) +
                                " values for a " + std::to_string(rows) + " x " +
                                std::to_string(cols) + " matrix");
  }
  WriteDataset(*file_, path_, name, data.data(), H5::PredType::IEEE_F32LE,
               H5::PredType::NATIVE_FLOAT, {rows, cols});
}

void Hdf5File::WriteFloatVector(const std::string& name, const std::vector<float>& data) {
  WriteDataset(*file_, path_, name, data.data(), H5::PredType::IEEE_F32LE,
               H5::PredType::NATIVE_FLOAT, {data.size()});
}

void Hdf5File::WriteIntVector(const std::string& name, const std::vector<std::int64_t>& data) {
  WriteDataset(*file_, path_, name, data.data(), H5::PredType::STD_I64LE,
               H5::PredType::NATIVE_INT64, {data.size()});
}

FloatMatrix Hdf5File::ReadFloatMatrix(const std::string& name, std::int64_t expected_cols) const {
  std::vector<hsize_t> dims(2);
  FloatMatrix matrix;
  matrix.data =
      ReadDataset<float>(*this, *file_, name, H5T_FLOAT, H5::PredType::NATIVE_FLOAT, dims);
  matrix.rows = dims[0];
  matrix.cols = dims[1];
  if (expected_cols >= 0 && matrix.cols != static_cast<std::size_t>(expected_cols)) {
    throw UserError(path_.string() + ": dataset '" + name + "' has " + std::to_string(matrix.cols) +
                    " columns, expected " + std::to_string(expected_cols));
  }
  return matrix;
}

std::vector<float> Hdf5File::ReadFloatVector(const std::string& name) const {
  std::vector<hsize_t> dims(1);
  return ReadDataset<float>(*this, *file_, name, H5T_FLOAT, H5::PredType::NATIVE_FLOAT, dims);
}

std::vector<std::int64_t> Hdf5File::ReadIntVector(const std::string& name) const {
  std::vector<hsize_t> dims(1);
  return ReadDataset<std::int64_t>(*this, *file_, name, H5T_INTEGER, H5::PredType::NATIVE_INT64,
                                   dims);
}

bool Hdf5File::HasAttribute(const std::string& name) const {
  return Guarded(path_, "read", [&] { return file_->attrExists(name); });
}

void Hdf5File::SetAttribute(const std::string& name, const std::string& value) {
  const H5::StrType type = Utf8StringType();
  WriteAttribute(*file_, path_, name, type, [&](H5::Attribute& a) { a.write(type, value); });
}

void Hdf5File::SetAttribute(const std::string& name, double value) {
  WriteAttribute(*file_, path_, name, H5::PredType::IEEE_F64LE,
                 [&](H5::Attribute& a) { a.write(H5::PredType::NATIVE_DOUBLE, &value); });
}

void Hdf5File::SetAttribute(const std::string& name, std::int64_t value) {
  WriteAttribute(*file_, path_, name, H5::PredType::STD_I64LE,
                 [&](H5::Attribute& a) { a.write(H5::PredType::NATIVE_INT64, &value); });
}

std::string Hdf5File::GetStringAttribute(const std::string& name) const {
  return ReadAttribute<std::string>(
      *this, *file_, name, H5T_STRING,
      [](const H5::Attribute& a, std::string& value) { a.read(a.getDataType(), value); });
}

double Hdf5File::GetDoubleAttribute(const std::string& name) const {
  return ReadAttribute<double>(
      *this, *file_, name, H5T_FLOAT,
      [](const H5::Attribute& a, double& value) { a.read(H5::PredType::NATIVE_DOUBLE, &value); });
}

std::int64_t Hdf5File::GetIntAttribute(const std::string& name) const {
  return ReadAttribute<std::int64_t>(*this, *file_, name, H5T_INTEGER,
                                     [](const H5::Attribute& a, std::int64_t& value) {
                                       a.read(H5::PredType::NATIVE_INT64, &value);
                                     });
}

}  // namespace colav
