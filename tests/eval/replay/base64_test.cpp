#include "eval/replay/base64.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

std::vector<std::uint8_t> Bytes(const std::string& text) { return {text.begin(), text.end()}; }

TEST(Base64, EncodesTheRfcExamples) {
  // RFC 4648, section 10.
  EXPECT_EQ(Base64Encode(Bytes("")), "");
  EXPECT_EQ(Base64Encode(Bytes("f")), "Zg==");
  EXPECT_EQ(Base64Encode(Bytes("fo")), "Zm8=");
  EXPECT_EQ(Base64Encode(Bytes("foo")), "Zm9v");
  EXPECT_EQ(Base64Encode(Bytes("foob")), "Zm9vYg==");
  EXPECT_EQ(Base64Encode(Bytes("fooba")), "Zm9vYmE=");
  EXPECT_EQ(Base64Encode(Bytes("foobar")), "Zm9vYmFy");
}

TEST(Base64, EveryByteValueRoundTrips) {
  for (std::size_t length = 0; length < 260; ++length) {
    std::vector<std::uint8_t> bytes(length);
    for (std::size_t i = 0; i < length; ++i) bytes[i] = static_cast<std::uint8_t>(255 - i);
    EXPECT_EQ(Base64Decode(Base64Encode(bytes)), bytes) << length;
  }
}

TEST(Base64, RefusesMalformedText) {
  EXPECT_THROW(Base64Decode("Zm9"), std::invalid_argument);
  EXPECT_THROW(Base64Decode("Zm9*"), std::invalid_argument);
}

}  // namespace
}  // namespace colav
