// The replay as the JSON document a replay page embeds. Bulk arrays are Base64 of little-endian
// float32 (positions, per-step numbers, moving vessels' poses) or of bytes (closeness), so a
// 2,000-step episode among 28 obstacles stays near 1 MB; the page decodes them with atob().
//
// {"format": 1, "name", "path": f32 [x, y]..., "circles": f32 [x, y, radius]...,
//  "vessel_widths": [...], "vessel_poses": f32 [step][vessel][x, y, heading],
//  "step_fields": [names of the per-step numbers, in order],
//  "runs": [{"label", "steps", "numbers": f32 [step][field], "closeness": u8 [step][ray],
//            "collisions": [steps with a collision]}]}
#pragma once

#include <nlohmann/json.hpp>

#include "eval/replay/replay.h"

namespace colav {

nlohmann::json ReplayJson(const Replay& replay);

/// The replay of ReplayJson's document; std::invalid_argument when it is not one.
Replay ReplayFromJson(const nlohmann::json& document);

}  // namespace colav
