#include "outputs/posture_csv.hpp"

#include <fmt/format.h>

namespace crux {

std::string posture_csv(const BodyModel& model, std::span<const Posture> postures, const char* index_name,
                        const std::vector<PostureCsvColumn>& columns) {
  std::string csv = index_name;
  for (const PostureCsvColumn& column : columns) csv += ',' + column.name;
  for (const BodyJoint& joint : model.joints) csv += ',' + joint.name;
  csv += '\n';
  for (std::size_t n = 0; n < postures.size(); ++n) {
    csv += fmt::format("{}", n);
    for (const PostureCsvColumn& column : columns) csv += ',' + column.cells.at(n);
    for (int i = 0; i < kConfigurationDof; ++i) csv += fmt::format(",{}", postures[n][i]);
    csv += '\n';
  }
  return csv;
}

}  // namespace crux
