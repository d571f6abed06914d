#include "climbing/policy_network.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/json_field.hpp"

namespace crux {

namespace {

constexpr const char* kPolicyFormat = "crux-policy";
constexpr int kPolicyVersion = 1;
constexpr const char* kPolicyObservation = "reach";

PolicyLayer read_layer(const JsonField& field) {
  field.expect_object();
  const JsonField weight = field["weight"];
  const JsonField bias = field["bias"];
  const auto outputs = static_cast<Eigen::Index>(weight.size());
  if (outputs == 0) weight.fail("has no rows");
  const auto inputs = static_cast<Eigen::Index>(weight[std::size_t{0}].size());
  bias.expect_size(static_cast<std::size_t>(outputs));
  PolicyLayer layer{Eigen::MatrixXf(outputs, inputs), Eigen::VectorXf(outputs)};
  for (Eigen::Index row = 0; row < outputs; ++row) {
    const JsonField values = weight[static_cast<std::size_t>(row)];
    values.expect_size(static_cast<std::size_t>(inputs));
    for (Eigen::Index column = 0; column < inputs; ++column) {
      const double value = values[static_cast<std::size_t>(column)].number();
      if (!std::isfinite(value)) values.fail("holds a value that is not finite");
      layer.weight(row, column) = static_cast<float>(value);
    }
    layer.bias(row) = static_cast<float>(bias[static_cast<std::size_t>(row)].number());
  }
  return layer;
}

void check_chain(const JsonField& layers, const std::vector<PolicyLayer>& read) {
  Eigen::Index inputs = kPolicyStateInputs + kPolicySlotInputs;
  for (const PolicyLayer& layer : read) {
    if (layer.weight.cols() != inputs) {
      layers.fail(fmt::format("has a layer of {} inputs where {} belong", layer.weight.cols(), inputs));
    }
    inputs = layer.weight.rows();
  }
  if (inputs != 1) layers.fail(fmt::format("ends in {} outputs, not one score", inputs));
}

}  // namespace

PolicyNetwork load_policy_network(const std::string& path) {
  const OrderedJson document = read_json_file(path, "policy file");
  const JsonField root(path, document);
  root.expect_object();
  if (!root.contains("format") || root["format"].json() != kPolicyFormat) {
    root.fail(fmt::format("not a policy file (its format is not \"{}\")", kPolicyFormat));
  }
  const std::string observation = root["observation"].string();
  const int version = root["version"].integer();
  if (observation != kPolicyObservation || version != kPolicyVersion) {
    root.fail(fmt::format("a policy for the \"{}\" observation, format version {}; crux reads \"{}\" version {}",
                          observation, version, kPolicyObservation, kPolicyVersion));
  }
  if (root["activation"].string() != "relu") root["activation"].fail("must be \"relu\"");
  PolicyNetwork network;
  network.source = path;
  network.max_span_m = root["max_span"].number();
  if (!(network.max_span_m > 0) || !std::isfinite(network.max_span_m)) root["max_span"].fail("must be > 0");
  const JsonField layers = root["slot_layers"];
  for (std::size_t i = 0; i < layers.size(); ++i) network.slot_layers.push_back(read_layer(layers[i]));
  if (network.slot_layers.empty()) layers.fail("has no layer");
  check_chain(layers, network.slot_layers);
  return network;
}

PolicyWorkspace::PolicyWorkspace(const BodyModel& model, const PolicyNetwork& network, int max_candidates_)
    : max_candidates(max_candidates_),
      body(model),
      free_limb(kLimbCount),
      held(3 * kLimbCount),
      candidates(3 * static_cast<std::size_t>(max_candidates_)),
      mask(static_cast<std::size_t>(max_candidates_)),
      posture(kConfigurationDof),
      centre_of_mass(3),
      to_finish(1),
      reach(kReachFeatures * static_cast<std::size_t>(max_candidates_)),
      failed(static_cast<std::size_t>(max_candidates_)),
      state(kPolicyStateInputs),
      slots(kPolicySlotInputs, max_candidates_) {
  Eigen::Index widest = 1;
  for (const PolicyLayer& layer : network.slot_layers) widest = std::max(widest, layer.weight.rows());
  first_from_state.resize(network.slot_layers.front().weight.rows());
  hidden.resize(widest, max_candidates_);
  next.resize(widest, max_candidates_);
}

namespace {

// The observation's floats as the network reads them: lengths over the span, as
// policy_baseline.py's batch_features.
void gather_inputs(PolicyWorkspace& w, int count, double span) {
  const auto scaled = [span](float value) { return static_cast<float>(value / span); };
  Eigen::Index i = 0;
  for (const float v : w.free_limb) w.state(i++) = v;
  for (const float v : w.held) w.state(i++) = scaled(v);
  for (int k = 0; k < kConfigurationDof; ++k) w.state(i++) = k < 3 ? scaled(w.posture[k]) : w.posture[k];
  for (const float v : w.centre_of_mass) w.state(i++) = scaled(v);
  w.state(i++) = scaled(w.to_finish[0]);
  for (int slot = 0; slot < count; ++slot) {
    Eigen::Index row = 0;
    for (int k = 0; k < 3; ++k) w.slots(row++, slot) = scaled(w.candidates[3 * slot + k]);
    for (int k = 0; k < kReachFeatures; ++k) w.slots(row++, slot) = scaled(w.reach[kReachFeatures * slot + k]);
    w.slots(row, slot) = w.failed[slot];
  }
}

}  // namespace

void score_candidates(const BodyModel& model, const PolicyNetwork& network, PolicyWorkspace& w,
                      const NumericObservationInput& state, std::span<double> scores) {
  const auto count = static_cast<int>(state.candidate_holds.size());
  write_numeric_observation(model, w.body, state, w.max_candidates,
                            {w.free_limb.data(), w.held.data(), w.candidates.data(), w.mask.data(), w.posture.data(),
                             w.centre_of_mass.data(), w.to_finish.data(), w.reach.data(), w.failed.data()});
  gather_inputs(w, count, network.max_span_m);
  // The first layer on [state, slot] is its state part, once, plus each slot's part.
  const PolicyLayer& first = network.slot_layers.front();
  const Eigen::Index width = first.weight.rows();
  w.first_from_state.noalias() = first.weight.leftCols(kPolicyStateInputs) * w.state;
  w.first_from_state += first.bias;
  auto in = w.hidden.topLeftCorner(width, count);
  in.noalias() = first.weight.rightCols(kPolicySlotInputs) * w.slots.leftCols(count);
  in.colwise() += w.first_from_state;
  Eigen::MatrixXf* current = &w.hidden;
  Eigen::MatrixXf* other = &w.next;
  Eigen::Index rows = width;
  for (std::size_t l = 1; l < network.slot_layers.size(); ++l) {
    const PolicyLayer& layer = network.slot_layers[l];
    auto input = current->topLeftCorner(rows, count);
    input = input.cwiseMax(0.0F);
    auto output = other->topLeftCorner(layer.weight.rows(), count);
    output.noalias() = layer.weight * input;
    output.colwise() += layer.bias;
    rows = layer.weight.rows();
    std::swap(current, other);
  }
  for (int slot = 0; slot < count; ++slot) scores[static_cast<std::size_t>(slot)] = (*current)(0, slot);
}

}  // namespace crux
