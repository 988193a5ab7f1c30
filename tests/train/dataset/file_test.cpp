#include "train/dataset/file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "src/error.h"
#include "src/hdf5_io.h"
#include "tests/src/test_util.h"
#include "tests/train/dataset/small_dataset.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

ScanDataset SmallDataset(std::uint64_t seed) {
  ScanDataset dataset = testing_util::SmallScanDataset(seed);
  dataset.config = "dataset:\n  seed: " + std::to_string(seed) + "\n";
  return dataset;
}

void ExpectOneLineMentioning(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(DatasetFileTest, RoundTripsAndIsDeterministicBySeed) {
  const TemporaryFolder folder;
  WriteScanDataset(SmallDataset(1), folder / "a.h5");
  WriteScanDataset(SmallDataset(1), folder / "b.h5");
  WriteScanDataset(SmallDataset(2), folder / "c.h5");
  const ScanDataset a = ReadScanDataset(folder / "a.h5");
  const ScanDataset b = ReadScanDataset(folder / "b.h5");
  const ScanDataset c = ReadScanDataset(folder / "c.h5");
  EXPECT_EQ(a.rows(), 180U);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_EQ(a.group, b.group);
  EXPECT_EQ(a.source_scan, b.source_scan);
  EXPECT_EQ(a.shift, b.shift);
  EXPECT_EQ(a.split, b.split);
  EXPECT_EQ(a.config, b.config);
  EXPECT_EQ(a.seed, 1);
  EXPECT_NE(a.ranges, c.ranges);
  const Hdf5File file = Hdf5File::Open(folder / "a.h5");
  EXPECT_NE(file.GetStringAttribute("description").find("ranges"), std::string::npos);
}

TEST(DatasetFileTest, BadInputIsAOneLineUserError) {
  const TemporaryFolder folder;
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "missing.h5"); }),
                          "missing.h5");

  WriteScanDataset(SmallDataset(1), folder / "good.h5");
  const auto size = std::filesystem::file_size(folder / "good.h5");
  std::filesystem::copy_file(folder / "good.h5", folder / "truncated.h5");
  std::filesystem::resize_file(folder / "truncated.h5", size / 2);
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "truncated.h5"); }),
                          "truncated.h5");

  testing_util::WriteFile(folder / "text.h5", "not an HDF5 file\n");
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "text.h5"); }),
                          "text.h5");

  Hdf5File::CreateAtomically(folder / "no_group.h5", [](Hdf5File& file) {
    file.WriteFloatMatrix("ranges", std::vector<float>(2 * kNumRays, 150.0F), 2, kNumRays);
  });
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "no_group.h5"); }),
                          "'group'");

  Hdf5File::CreateAtomically(folder / "narrow.h5", [](Hdf5File& file) {
    file.WriteFloatMatrix("ranges", std::vector<float>(2 * 179, 150.0F), 2, 179);
  });
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "narrow.h5"); }),
                          "'ranges'");

  Hdf5File::CreateAtomically(folder / "bad_split.h5", [](Hdf5File& file) {
    file.WriteFloatMatrix("ranges", std::vector<float>(2 * kNumRays, 150.0F), 2, kNumRays);
    for (const char* name : {"group", "source_scan", "shift"}) file.WriteIntVector(name, {0, 0});
    file.WriteIntVector("split", {0, 7});
  });
  ExpectOneLineMentioning(UserErrorMessage([&] { ReadScanDataset(folder / "bad_split.h5"); }),
                          "'split'");
}

}  // namespace
}  // namespace colav
