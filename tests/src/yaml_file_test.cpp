#include "src/yaml_file.h"

#include <gtest/gtest.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
using testing_util::WriteFile;

TEST(YamlFileTest, ParsesAFile) {
  TemporaryFolder folder;
  WriteFile(folder / "s.yaml", "path:\n  waypoints: [[0, 0], [0, 250]]\n");
  const YAML::Node root = LoadYamlFile(folder / "s.yaml");
  EXPECT_EQ(root["path"]["waypoints"][1][1].as<double>(), 250.0);
}

TEST(YamlFileTest, MissingFileAndFolderAreNamed) {
  TemporaryFolder folder;
  EXPECT_EQ(UserErrorMessage([&] { LoadYamlFile(folder / "none.yaml"); }),
            (folder / "none.yaml").string() + ": no such file");
  EXPECT_EQ(UserErrorMessage([&] { LoadYamlFile(folder.path()); }),
            folder.path().string() + ": is a folder, not a file");
}

TEST(YamlFileTest, MalformedYamlGivesLineAndColumnFromOne) {
  TemporaryFolder folder;
  WriteFile(folder / "bad.yaml", "a: 1\nb: [1, 2\n");
  EXPECT_EQ(UserErrorMessage([&] { LoadYamlFile(folder / "bad.yaml"); }),
            (folder / "bad.yaml").string() +
                ": malformed YAML at line 3, column 1: end of sequence flow not found");
}

TEST(YamlFileTest, DuplicateKeysAreNamedWithTheirLine) {
  TemporaryFolder folder;
  WriteFile(folder / "top.yaml", "a: 1\nb: 2\na: 3\n");
  EXPECT_EQ(UserErrorMessage([&] { LoadYamlFile(folder / "top.yaml"); }),
            (folder / "top.yaml").string() + ": line 3: duplicate key 'a'");
  WriteFile(folder / "nested.yaml", "env:\n  x: 1\nlist:\n  - {r: 1, r: 2}\n");
  EXPECT_EQ(UserErrorMessage([&] { LoadYamlFile(folder / "nested.yaml"); }),
            (folder / "nested.yaml").string() + ": line 4: duplicate key 'r'");
  WriteFile(folder / "same_name_elsewhere.yaml", "a: {x: 1}\nb: {x: 2}\n");
  EXPECT_NO_THROW(LoadYamlFile(folder / "same_name_elsewhere.yaml"));
}

}  // namespace
}  // namespace colav
