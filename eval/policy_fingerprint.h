// What identifies a policy's behaviour in an evaluation, as one string: its file's bytes and its
// sidecar's (the observation settings it may take from there), so an evaluation can tell whether
// episodes recorded earlier for a model still stand (eval/reused_episodes.h).
#pragma once

#include <filesystem>
#include <string>

namespace colav {

/// "fnv1a64:<16 hex digits>": the 64-bit FNV-1a hash of the policy file's bytes, then of its
/// sidecar's (SidecarPath) when there is one. A change detector, not a cryptographic digest. An
/// unreadable file is a UserError naming it.
std::string PolicyFingerprint(const std::filesystem::path& policy);

}  // namespace colav
