#pragma once
// Wall files: the versioned JSON format "crux-wall", versions 1 and 2 (docs/OUTPUTS.md,
// docs/wall.schema.json). Version 2 adds an optional "incline" (degrees from vertical,
// in (-90, 90); docs/MODEL.md, choice C25) and an optional "support" direction per hold
// ([x, y, z], any non-zero length, stored as a unit vector). A wall without either is
// written as version 1, so that such files keep their bytes.
//
//   {"format": "crux-wall", "version": 1, "name": "...", "finish_height": 2.5,
//    "start": {"right_hand": ID, "left_hand": ID, "right_foot": ID, "left_foot": ID},
//    "holds": [{"id": 1, "position": [x, y, z], "radius": 0.04}, ...]}
//
// The file names start holds by id; in memory Wall::start holds indices into
// Wall::holds, whose order is the file's order. Holds are meant to lie on the wall
// plane x = 0, but any finite x is accepted (a hold standing out of the wall, towards the
// climber at x < 0, is legal).
//
// Reading is strict so that a typo never silently changes a wall: unknown keys and
// duplicate keys are rejected, as are missing or mistyped fields, non-finite numbers,
// non-positive radii, duplicate or non-positive hold ids, fewer than 4 holds, and a
// start naming an unknown hold or one hold for two limbs. Every problem is one
// InputError(source, problem) whose problem is a single line naming the field.

#include <string>

#include "wall/wall.hpp"

namespace crux {

inline constexpr const char* kWallFormatName = "crux-wall";
inline constexpr int kWallFormatVersion = 2;  // the newest; 1 is still read and written

// Reads and validates a wall file; InputError(path, problem) on any problem.
Wall load_wall(const std::string& path);

// Validates wall JSON; `source` names it in errors (a path, or e.g. "<stdin>").
Wall parse_wall(const std::string& json_text, const std::string& source);

// Deterministic, human-editable text: 2-space indent, one hold per line, numbers
// printed so they read back bit for bit.
std::string wall_to_json(const Wall& wall);

// Writes wall_to_json(wall) atomically. Refuses (InputError naming `path`, nothing
// written) a wall that would not load back, e.g. with a non-finite coordinate.
void save_wall(const std::string& path, const Wall& wall);

}  // namespace crux
