// Turns the layers of one LOD set (each already converted to a neutral Level with its
// switch distances and center) into one LodModel, finest level first, after checking
// that the set is usable: one layer per level number, level 0 present, every level with
// a range (switchOut < switchIn) and ranges that move outwards with the level number.
#pragma once

#include "openflight/lod_model.h"

#include <string>
#include <vector>

namespace cadlod::flt {

struct LodSetMember {
    int setId = 0;
    int level = 0;  // 0 = original, finest
    Level geometry;
};

// Members of other sets are ignored. False with `error` when the set is not usable.
bool assembleLodSet(std::vector<LodSetMember> members, int setId, LodModel& model, std::string& error);

}  // namespace cadlod::flt
