// Base64 (RFC 4648, with padding) of byte strings: how the replay file carries its binary arrays
// inside JSON, for the page's atob() to read back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace colav {

std::string Base64Encode(const std::vector<std::uint8_t>& bytes);

/// The bytes of a Base64 text; std::invalid_argument on a character outside the alphabet or a
/// length that is not a multiple of 4.
std::vector<std::uint8_t> Base64Decode(const std::string& text);

}  // namespace colav
