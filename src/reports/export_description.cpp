#include "reports/export_description.hpp"

#include <fmt/format.h>

namespace crux {

MjcfExport describe_mjcf_export(const std::string& file, const BodyModel& model, const Wall& wall) {
  return {file, model.name, model.total_mass, kRevoluteDof, wall.name, wall.incline_deg, wall.hold_count()};
}

nlohmann::ordered_json mjcf_export_json(const MjcfExport& written) {
  nlohmann::ordered_json out;
  out["file"] = written.file;
  out["format"] = "mjcf";
  out["body"] = written.body;
  out["mass_kg"] = written.mass_kg;
  out["motors"] = written.joints;
  out["root"] = "free";
  out["wall"] = written.wall;
  out["incline_deg"] = written.incline_deg;
  out["holds"] = written.holds;
  return out;
}

std::string mjcf_export_text(const MjcfExport& written) {
  return fmt::format("wrote {}: {} ({:.1f} kg, {} motors, free root) on {} ({} holds, {:g} degrees)\n", written.file,
                     written.body, written.mass_kg, written.joints, written.wall, written.holds, written.incline_deg);
}

}  // namespace crux
