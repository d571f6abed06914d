#include "configurations/configuration_keys.hpp"

#include "ik/ik_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_reachability_keys(FieldsFor<Parameters>& keys, Parameters& reachability) {
  ik_keys(keys, reachability.ik);
  keys.insert(
      keys.end(),
      {
          {"ik.wall_distance", "Distance of the root target H(C4) from the wall, on the climber's side",
           &reachability.root.distance_from_wall, "m", closed_range(-kMaxLengthM, kMaxLengthM)},
          {"ik.cache_unreachable", "Cache unreachable verdicts", &reachability.cache_unreachable},
          {"ik.guess",
           "Where the IK starts a configuration's solve: previous (the posture the climber holds, the paper's) or "
           "standing (the standing posture at the configuration's root target, so that a verdict does not depend on "
           "the climb)",
           choice_of(&reachability.guess)},
      });
}

template <typename Parameters>
void declare_filter_keys(FieldsFor<Parameters>& keys, Parameters& filter) {
  keys.insert(keys.end(), {
                              {"filter.max_span", "Largest distance between two holds of a configuration",
                               &filter.max_span_m, "m", kLength},
                              {"filter.reading", "Reading of 'both feet above the hands' (docs/MODEL.md, choice C13)",
                               choice_of(&filter.feet_above_hands)},
                          });
}

}  // namespace

void reachability_keys(std::vector<ConfigField>& keys, ReachabilityParameters& reachability) {
  declare_reachability_keys(keys, reachability);
}
void reachability_keys(std::vector<ConstConfigField>& keys, const ReachabilityParameters& reachability) {
  declare_reachability_keys(keys, reachability);
}

void filter_keys(std::vector<ConfigField>& keys, FilterParameters& filter) { declare_filter_keys(keys, filter); }
void filter_keys(std::vector<ConstConfigField>& keys, const FilterParameters& filter) {
  declare_filter_keys(keys, filter);
}

}  // namespace crux
