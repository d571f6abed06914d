#include "physics/balance_precheck.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace crux {
namespace {

// The program accepts row residuals and bound violations of 1e-7 (CLP's primal
// tolerance, unscaled); a projection sums a few dozen of them, each times a lever of a
// few metres. Real refusals miss by newtons or newton-metres.
constexpr double kPrecheckAbsoluteMargin = 1e-3;
constexpr double kPrecheckRelativeMargin = 1e-6;

// Whether `target` lies outside the range of sum_c f_c . directions[c] over the forces
// the contacts admit: each contact ranges over [L min(0, min_k s_k), L max(0, max_k s_k)]
// with s_k = directions[c] . g_k, unbounded on a side where L is infinite and some s_k
// has that side's sign.
bool projection_out_of_reach(std::span<const HeldContact> contacts, std::span<const Eigen::Vector3d> directions,
                             double target) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double low = 0.0, high = 0.0;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    double smallest = 0.0, largest = 0.0;
    for (const Eigen::Vector3d& generator : contacts[c].generators) {
      const double s = directions[c].dot(generator);
      smallest = std::min(smallest, s);
      largest = std::max(largest, s);
    }
    const double limit = contacts[c].normal_force_limit;
    low += smallest < 0.0 ? (std::isfinite(limit) ? limit * smallest : -kInfinity) : 0.0;
    high += largest > 0.0 ? (std::isfinite(limit) ? limit * largest : kInfinity) : 0.0;
  }
  const double margin = kPrecheckAbsoluteMargin + kPrecheckRelativeMargin * std::abs(target);
  return target > high + margin || target < low - margin;
}

}  // namespace

bool proven_unbalanced(std::span<const HeldContact> contacts, const Eigen::Vector3d& force,
                       const Eigen::Vector3d& moment) {
  constexpr std::size_t kMaxContacts = 4;
  if (contacts.size() > kMaxContacts) return false;
  std::array<Eigen::Vector3d, kMaxContacts> storage;
  const std::span<Eigen::Vector3d> directions(storage.data(), contacts.size());
  // The force equations along a direction e: sum_c f_c . e = force . e.
  const Eigen::Vector3d force_direction =
      force.norm() > 0.0 ? Eigen::Vector3d(force.normalized()) : Eigen::Vector3d::UnitZ();
  for (const Eigen::Vector3d& e : {Eigen::Vector3d(Eigen::Vector3d::UnitX()), Eigen::Vector3d(Eigen::Vector3d::UnitY()),
                                   Eigen::Vector3d(Eigen::Vector3d::UnitZ()), force_direction}) {
    std::fill(directions.begin(), directions.end(), e);
    if (projection_out_of_reach(contacts, directions, force.dot(e))) return true;
  }
  // The moment about the line through contacts a and b, direction u:
  // sum_c f_c . (u x (l_c - l_a)) = u . (moment - l_a x force). The two contacts on the
  // line have no lever about it: their terms are zero exactly, not by rounding.
  for (std::size_t a = 0; a < contacts.size(); ++a) {
    for (std::size_t b = a + 1; b < contacts.size(); ++b) {
      const Eigen::Vector3d span = contacts[b].lever - contacts[a].lever;
      if (!(span.norm() > 1e-6)) continue;
      const Eigen::Vector3d u = span.normalized();
      for (std::size_t c = 0; c < contacts.size(); ++c) {
        directions[c] = c == a || c == b ? Eigen::Vector3d::Zero()
                                         : Eigen::Vector3d(u.cross(contacts[c].lever - contacts[a].lever));
      }
      if (projection_out_of_reach(contacts, directions, u.dot(moment - contacts[a].lever.cross(force)))) return true;
    }
  }
  return false;
}

}  // namespace crux
