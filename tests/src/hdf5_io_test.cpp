#include "src/hdf5_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <numeric>
#include <stdexcept>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

std::vector<float> Ramp(std::size_t count) {
  std::vector<float> values(count);
  std::iota(values.begin(), values.end(), 0.25F);
  return values;
}

class Hdf5IoTest : public ::testing::Test {
 protected:
  // Writes a 4 x 180 matrix "ranges", a float vector "/stats/mean" and an int vector "labels".
  void WriteSample() {
    Hdf5File::CreateAtomically(path_, [](Hdf5File& file) {
      file.WriteFloatMatrix("ranges", Ramp(4 * 180), 4, 180);
      file.WriteFloatVector("/stats/mean", {1.5F, -2.0F});
      file.WriteIntVector("labels", {0, 1, -7, 1LL << 40});
    });
  }

  TemporaryFolder folder_;
  std::filesystem::path path_ = folder_ / "data.h5";
};

TEST_F(Hdf5IoTest, DatasetsRoundTrip) {
  WriteSample();
  const Hdf5File file = Hdf5File::Open(path_);
  const FloatMatrix ranges = file.ReadFloatMatrix("ranges", 180);
  EXPECT_EQ(ranges.rows, 4U);
  EXPECT_EQ(ranges.cols, 180U);
  EXPECT_EQ(ranges.data, Ramp(4 * 180));
  EXPECT_THAT(file.ReadFloatVector("/stats/mean"), ElementsAre(1.5F, -2.0F));
  EXPECT_THAT(file.ReadFloatVector("stats/mean"), ElementsAre(1.5F, -2.0F));
  EXPECT_THAT(file.ReadIntVector("labels"), ElementsAre(0, 1, -7, 1LL << 40));
  EXPECT_EQ(file.ReadFloatMatrix("ranges").cols, 180U);  // any number of columns
}

TEST_F(Hdf5IoTest, EmptyDatasetsRoundTrip) {
  Hdf5File::CreateAtomically(path_, [](Hdf5File& file) {
    file.WriteFloatMatrix("empty", {}, 0, 180);
    file.WriteIntVector("none", {});
  });
  const Hdf5File file = Hdf5File::Open(path_);
  const FloatMatrix empty = file.ReadFloatMatrix("empty", 180);
  EXPECT_EQ(empty.rows, 0U);
  EXPECT_TRUE(empty.data.empty());
  EXPECT_TRUE(file.ReadIntVector("none").empty());
}

TEST_F(Hdf5IoTest, HasDatasetFollowsGroups) {
  WriteSample();
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_TRUE(file.HasDataset("ranges"));
  EXPECT_TRUE(file.HasDataset("/stats/mean"));
  EXPECT_FALSE(file.HasDataset("stats"));  // a group, not a dataset
  EXPECT_FALSE(file.HasDataset("stats/median"));
  EXPECT_FALSE(file.HasDataset("no/such/group"));
}

TEST_F(Hdf5IoTest, AttributesRoundTrip) {
  Hdf5File::CreateAtomically(path_, [](Hdf5File& file) {
    file.SetAttribute("source", "simulator + synthetic");
    file.SetAttribute("noise_variance", 0.007);
    file.SetAttribute("scans", std::int64_t{20000});
    file.SetAttribute("seed", std::uint64_t{12345});
    file.SetAttribute("rotations", 2);
    file.SetAttribute("scans", std::int64_t{60000});  // replaces
  });
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_EQ(file.GetStringAttribute("source"), "simulator + synthetic");
  EXPECT_DOUBLE_EQ(file.GetDoubleAttribute("noise_variance"), 0.007);
  EXPECT_EQ(file.GetIntAttribute("scans"), 60000);
  EXPECT_EQ(file.GetIntAttribute("seed"), 12345);
  EXPECT_EQ(file.GetIntAttribute("rotations"), 2);
  EXPECT_TRUE(file.HasAttribute("seed"));
  EXPECT_FALSE(file.HasAttribute("missing"));
}

TEST_F(Hdf5IoTest, UnsignedAttributeBeyondInt64IsRejected) {
  EXPECT_THROW(Hdf5File::CreateAtomically(
                   path_, [](Hdf5File& file) { file.SetAttribute("seed", ~std::uint64_t{0}); }),
               std::out_of_range);
  EXPECT_FALSE(std::filesystem::exists(path_));
}

TEST_F(Hdf5IoTest, MissingFileIsNamed) {
  EXPECT_EQ(UserErrorMessage([&] { Hdf5File::Open(path_); }), path_.string() + ": no such file");
}

TEST_F(Hdf5IoTest, NonHdf5FileIsRejected) {
  testing_util::WriteFile(path_, "ranges\n1,2,3\n");
  EXPECT_EQ(UserErrorMessage([&] { Hdf5File::Open(path_); }),
            path_.string() + ": not an HDF5 file, or damaged or truncated");
}

TEST_F(Hdf5IoTest, TruncatedFileIsAUserError) {
  Hdf5File::CreateAtomically(
      path_, [](Hdf5File& file) { file.WriteFloatMatrix("ranges", Ramp(2000 * 180), 2000, 180); });
  std::filesystem::resize_file(path_, std::filesystem::file_size(path_) / 2);
  const std::string message = UserErrorMessage([&] {
    const Hdf5File file = Hdf5File::Open(path_);
    file.ReadFloatMatrix("ranges", 180);
  });
  EXPECT_THAT(message, HasSubstr(path_.string() + ": "));
  EXPECT_THAT(message, HasSubstr("truncated"));
}

TEST_F(Hdf5IoTest, MissingDatasetIsNamed) {
  WriteSample();
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_EQ(UserErrorMessage([&] { file.ReadFloatMatrix("scans", 180); }),
            path_.string() + ": no dataset 'scans'");
  EXPECT_EQ(UserErrorMessage([&] { file.ReadIntVector("stats/labels"); }),
            path_.string() + ": no dataset 'stats/labels'");
}

TEST_F(Hdf5IoTest, WrongShapeIsNamed) {
  Hdf5File::CreateAtomically(
      path_, [](Hdf5File& file) { file.WriteFloatMatrix("ranges", Ramp(2 * 179), 2, 179); });
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_EQ(UserErrorMessage([&] { file.ReadFloatMatrix("ranges", 180); }),
            path_.string() + ": dataset 'ranges' has 179 columns, expected 180");
  EXPECT_EQ(UserErrorMessage([&] { file.ReadFloatVector("ranges"); }),
            path_.string() + ": dataset 'ranges' has 2 dimensions, expected 1");
}

TEST_F(Hdf5IoTest, WrongValueTypeIsNamed) {
  WriteSample();
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_EQ(UserErrorMessage([&] { file.ReadFloatVector("labels"); }),
            path_.string() + ": dataset 'labels' holds integer values, expected floating-point");
  EXPECT_EQ(UserErrorMessage([&] { file.GetStringAttribute("missing"); }),
            path_.string() + ": no attribute 'missing'");
}

TEST_F(Hdf5IoTest, WrongAttributeTypeIsNamed) {
  Hdf5File::CreateAtomically(path_, [](Hdf5File& file) { file.SetAttribute("seed", 7); });
  const Hdf5File file = Hdf5File::Open(path_);
  EXPECT_EQ(UserErrorMessage([&] { file.GetStringAttribute("seed"); }),
            path_.string() + ": attribute 'seed' is integer, expected string");
}

TEST_F(Hdf5IoTest, FailedCreationLeavesOldFileAndNoTemporary) {
  WriteSample();
  EXPECT_THROW(Hdf5File::CreateAtomically(path_,
                                          [](Hdf5File& file) {
                                            file.WriteFloatVector("partial", {1.0F});
                                            throw std::runtime_error("generator failed");
                                          }),
               std::runtime_error);
  EXPECT_THAT(folder_.Entries(), ElementsAre("data.h5"));
  EXPECT_TRUE(Hdf5File::Open(path_).HasDataset("ranges"));
}

TEST_F(Hdf5IoTest, MatrixSizeMismatchIsAProgrammingError) {
  EXPECT_THROW(Hdf5File::CreateAtomically(
                   path_, [](Hdf5File& file) { file.WriteFloatMatrix("m", Ramp(5), 2, 3); }),
               std::invalid_argument);
}

// The first Python that has h5py: Debian installs it for the system interpreter, which a pyenv or
// venv python3 earlier on the PATH does not see.
std::string PythonWithH5py() {
  for (const std::string python : {"python3", "/usr/bin/python3"}) {
    if (std::system((python + " -c 'import h5py' 2>/dev/null").c_str()) == 0) return python;
  }
  return "";
}

// The Python tools (h5py) must read what we write, strings as str.
TEST_F(Hdf5IoTest, H5pyReadsTheFile) {
  const std::string python = PythonWithH5py();
  ASSERT_FALSE(python.empty())
      << "no python3 with h5py (install python3-h5py: scripts/install_deps.sh)";
  Hdf5File::CreateAtomically(path_, [](Hdf5File& file) {
    file.WriteFloatMatrix("/scans/ranges", Ramp(3 * 180), 3, 180);
    file.SetAttribute("source", "simulator");
  });
  const std::string check =
      python +
      " -c \"import h5py, sys; f = h5py.File(sys.argv[1], 'r'); "
      "d = f['scans/ranges']; "
      "assert d.shape == (3, 180) and d.dtype == 'float32' and d[0, 1] == 1.25; "
      "assert f.attrs['source'] == 'simulator'\" " +
      path_.string();
  EXPECT_EQ(std::system(check.c_str()), 0);
}

}  // namespace
}  // namespace colav
