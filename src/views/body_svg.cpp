#include "views/body_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "views/axis_ticks.hpp"
#include "views/legend.hpp"
#include "views/palette.hpp"
#include "views/svg_document.hpp"
#include "wall/incline.hpp"

namespace crux {
namespace {

constexpr double kBodyMargin = 12;
constexpr double kHeaderHeight = 52;
constexpr double kAxisRoom = 44;    // left of each panel: z tick labels and title
constexpr double kBelowPanel = 40;  // horizontal tick labels and axis title
constexpr double kPanelGap = 30;
constexpr double kPadding = 0.15;  // metres of wall around what is drawn
// The legend flows across the page under the panels, items 14 pixels apart.
constexpr LegendLayout kBodyLegendLayout{11, 30, 24, true};
constexpr double kBodyLegendGap = 14;
constexpr double kMaxPanelPixels = 20000;  // the larger extent of the drawing, at most
constexpr int kCylinderSides = 24;
constexpr const char* kHoldBesideBodyColour = "#555555";
constexpr const char* kWallColour = "#9a8f80";

using Point = std::array<double, 2>;  // on the page, in pixels

// Andrew's monotone chain: the outline of a projected box or cylinder.
std::vector<Point> convex_hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  const auto cross = [](const Point& o, const Point& a, const Point& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::string colour(const std::array<double, 4>& rgba, double shade) {
  const auto channel = [&](double c) { return static_cast<int>(std::lround(std::clamp(c * shade, 0.0, 1.0) * 255)); };
  return fmt::format("#{:02x}{:02x}{:02x}", channel(rgba[0]), channel(rgba[1]), channel(rgba[2]));
}

// A visual placed in the world: its centre, axes (columns) and the points of its outline.
struct PlacedVisual {
  const BodyVisual* visual;
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes;
  std::vector<Eigen::Vector3d> outline;  // empty for a sphere
};

std::vector<PlacedVisual> place_visuals(const BodyModel& model, const BodyData& data) {
  std::vector<PlacedVisual> placed;
  for (const BodyVisual& visual : model.visuals) {
    const JointPlacement& carrier = data.placements[visual.joint];
    PlacedVisual p{
        &visual, carrier.origin + carrier.rotation * visual.translation, carrier.rotation * visual.rotation, {}};
    const Eigen::Vector3d& s = visual.size;
    if (visual.shape == VisualShape::Box) {
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d local((corner & 1 ? 0.5 : -0.5) * s.x(), (corner & 2 ? 0.5 : -0.5) * s.y(),
                                    (corner & 4 ? 0.5 : -0.5) * s.z());
        p.outline.push_back(p.centre + p.axes * local);
      }
    } else if (visual.shape == VisualShape::Cylinder) {
      for (int k = 0; k < kCylinderSides; ++k) {
        const double angle = 2 * std::numbers::pi * k / kCylinderSides;
        for (const double end : {-0.5, 0.5}) {
          const Eigen::Vector3d local(s.x() * std::cos(angle), s.x() * std::sin(angle), end * s.y());
          p.outline.push_back(p.centre + p.axes * local);
        }
      }
    }
    placed.push_back(std::move(p));
  }
  return placed;
}

// One orthographic view: `horizontal` picks the world coordinate drawn left to right
// (with its sign), z is drawn up; `depth` grows towards the viewer.
struct View {
  const char* title;
  std::string axis_title;
  int horizontal_axis;
  double horizontal_sign;
  int depth_axis;
  double depth_sign;
  double low = 0, high = 0;  // the horizontal extent, in world metres along the axis
  double left = 0, top = 0, scale = 1, z_top = 0;

  double u(const Eigen::Vector3d& p) const { return horizontal_sign * p[horizontal_axis]; }
  double x_of(double world_u) const { return left + (world_u - low) * scale; }
  Point project(const Eigen::Vector3d& p) const { return {x_of(u(p)), top + (z_top - p.z()) * scale}; }
  double depth(const Eigen::Vector3d& p) const { return depth_sign * p[depth_axis]; }
  double width() const { return (high - low) * scale; }
};

class BodyFigure {
 public:
  BodyFigure(const BodyModel& model, const Posture& posture, const Wall& wall, const BodySvgOptions& options)
      : model_(model), wall_(wall), options_(options), data_(model) {
    forward_kinematics(model, data_, posture);
    // Only a turned root moves the frames, so that an unturned drawing keeps its bytes.
    if (options.root_rotation.coeffs() != Eigen::Quaterniond::Identity().coeffs()) {
      turn_about_root(data_, options.root_rotation);
    }
    visuals_ = place_visuals(model, data_);
    holds_ = wall.holds;
    // An inclined wall is drawn as it stands, gravity down: every point turns from wall
    // coordinates to the world's (docs/MODEL.md, choice C25). A vertical wall is left as is.
    if (wall.incline_deg != 0.0) {
      tilt_ = wall_to_world(wall.incline_deg);
      for (PlacedVisual& v : visuals_) {
        v.centre = tilt_ * v.centre;
        v.axes = tilt_ * v.axes;
        for (Eigen::Vector3d& p : v.outline) p = tilt_ * p;
      }
      for (Hold& hold : holds_) hold.position = tilt_ * hold.position;
    }
    lay_out();
  }

  std::string render() {
    append_format(out_, "<text x=\"{}\" y=\"{}\" font-size=\"15\" font-weight=\"bold\" fill=\"{}\">{}</text>\n",
                  kBodyMargin, kBodyMargin + 14, kTitleColour, xml_escaped(options_.title));
    append_format(out_, "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"{}\">{}</text>\n", kBodyMargin,
                  kBodyMargin + 32, kSubtitleColour, xml_escaped(options_.subtitle));
    for (const View& view : views_) write_panel(view);
    draw_legend_at(out_, kBodyMargin + kHeaderHeight + panel_height_ + kBelowPanel, legend_, legend_places_,
                   kBodyLegendLayout);
    return svg_document(width_, height_, options_.title, out_);
  }

 private:
  Eigen::Vector3d grasp_point(int limb) const {
    const Eigen::Vector3d& point = data_.points[operational_point(static_cast<Limb>(limb))];
    return wall_.incline_deg != 0.0 ? Eigen::Vector3d(tilt_ * point) : point;
  }

  double finish_world_z() const {
    return wall_.incline_deg != 0.0 ? (tilt_ * Eigen::Vector3d(0.0, 0.0, wall_.finish_height)).z()
                                    : wall_.finish_height;
  }

  // The side view's u of the wall plane at world height z: the plane leans by the incline.
  double wall_u(double z) const { return z * std::tan(wall_.incline_deg * std::numbers::pi / 180.0); }

  void lay_out() {
    // Both are views of the right-handed world as a camera sees it. Front: from behind
    // the climber (from x < 0, looking at the wall along +x), so the climber's left (+y)
    // is on the left. Side: from the climber's left (from +y), the wall on the left and
    // the climber, at x < 0, to its right.
    views_ = {View{"front, from behind the climber", "y (m), to the climber's left", 1, -1.0, 0, -1.0},
              View{"side, from the climber's left", "x (m); the wall is x = 0, the climber at x < 0", 0, -1.0, 1, 1.0}};
    if (wall_.incline_deg != 0.0) {
      views_[1].axis_title =
          fmt::format("x (m), horizontal; the wall, inclined {:g} degrees, stands on x = 0", wall_.incline_deg);
    }
    double z_low = std::min(0.0, finish_world_z()), z_high = finish_world_z();
    const auto include = [&](View& view, const Eigen::Vector3d& p, double radius) {
      view.low = std::min(view.low, view.u(p) - radius);
      view.high = std::max(view.high, view.u(p) + radius);
    };
    for (View& view : views_) {
      view.low = std::numeric_limits<double>::infinity();
      view.high = -view.low;
      for (const Hold& hold : holds_) include(view, hold.position, hold.radius);
      for (const PlacedVisual& v : visuals_) {
        if (v.outline.empty()) include(view, v.centre, v.visual->size.x());
        for (const Eigen::Vector3d& p : v.outline) include(view, p, 0.0);
      }
      include(view, Eigen::Vector3d::Zero(), 0.0);  // the wall plane is always in the side view
      view.low -= kPadding;
      view.high += kPadding;
    }
    for (const Hold& hold : holds_) {
      z_low = std::min(z_low, hold.position.z() - hold.radius);
      z_high = std::max(z_high, hold.position.z() + hold.radius);
    }
    for (const PlacedVisual& v : visuals_) {
      const double r = v.outline.empty() ? v.visual->size.x() : 0.0;
      z_low = std::min(z_low, v.centre.z() - r);
      z_high = std::max(z_high, v.centre.z() + r);
      for (const Eigen::Vector3d& p : v.outline) {
        z_low = std::min(z_low, p.z());
        z_high = std::max(z_high, p.z());
      }
    }
    z_low_ = z_low - kPadding;
    z_top_ = z_high + kPadding;
    // A wall far larger than a climber is drawn smaller, so that the page and its number
    // of metre lines stay bounded.
    double span = z_top_ - z_low_;
    for (const View& view : views_) span = std::max(span, view.high - view.low);
    if (!std::isfinite(span)) throw std::invalid_argument("render_body_svg: the wall is too large to draw");
    const double scale = std::min(options_.pixels_per_metre, kMaxPanelPixels / span);
    tick_spacing_ = metre_tick_spacing(scale);
    double left = kBodyMargin;
    for (View& view : views_) {
      view.left = left + kAxisRoom;
      view.top = kBodyMargin + kHeaderHeight;
      view.scale = scale;
      view.z_top = z_top_;
      left = view.left + view.width() + kPanelGap;
    }
    panel_height_ = (z_top_ - z_low_) * scale;
    width_ = std::ceil(std::max(left - kPanelGap + kBodyMargin,
                                2 * kBodyMargin + std::max(estimated_text_width(options_.title, 15),
                                                           estimated_text_width(options_.subtitle, 11))));
    for (const View& view : views_) {
      width_ = std::max(width_, std::ceil(view.left + estimated_text_width(view.title, 12) + kBodyMargin));
    }
    legend_ = legend_items();
    legend_places_ = flowing_legend_places(legend_, kBodyLegendLayout, kBodyLegendGap, kBodyMargin, width_);
    const int legend_rows = legend_places_.empty() ? 1 : legend_places_.back().row + 1;
    height_ = std::ceil(kBodyMargin + kHeaderHeight + panel_height_ + kBelowPanel +
                        kBodyLegendLayout.row_height * legend_rows + kBodyMargin);
  }

  void write_panel(const View& view) {
    const double bottom = view.top + panel_height_;
    append_format(out_, "<g class=\"panel\">\n<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"12\" fill=\"{}\">{}</text>\n",
                  view.left, view.top - 6, kTextColour, view.title);
    // Metre lines and their labels.
    const std::vector<double> z_ticks = metre_ticks(z_low_, z_top_, tick_spacing_);
    const std::vector<double> u_ticks = metre_ticks(view.low, view.high, tick_spacing_);
    append_format(out_, "<g stroke=\"{}\" stroke-width=\"1\">\n", kBodyMetreLineColour);
    for (const double z : z_ticks) {
      draw_horizontal_line(out_, view.left, view.left + view.width(), view.top + (z_top_ - z) * view.scale);
    }
    for (const double u : u_ticks) draw_vertical_line(out_, view.x_of(u), view.top, bottom);
    append_format(out_, "</g>\n<g font-size=\"10\" fill=\"{}\">\n", kSubtitleColour);
    for (const double z : z_ticks) {
      draw_plain_text(out_, view.left - 4, view.top + (z_top_ - z) * view.scale + 3.5, metre_tick_label(z), "end");
    }
    for (const double u : u_ticks) {
      // The label is the world coordinate, whose sign the front view flips.
      draw_plain_text(out_, view.x_of(u), bottom + 14, metre_tick_label(view.horizontal_sign * u), "middle");
    }
    out_ += "</g>\n";
    append_format(out_,
                  "<text x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"11\" fill=\"{}\" text-anchor=\"middle\">{}</text>\n",
                  view.left + view.width() / 2, bottom + 32, kTextColour, xml_escaped(view.axis_title));
    append_format(out_,
                  "<text x=\"{0:.2f}\" y=\"{1:.2f}\" font-size=\"11\" fill=\"{2}\" text-anchor=\"middle\" "
                  "transform=\"rotate(-90 {0:.2f} {1:.2f})\">z (m), up</text>\n",
                  view.left - 32, view.top + panel_height_ / 2, kTextColour);
    append_format(out_,
                  "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" stroke=\"{}\"/>\n",
                  view.left, view.top, view.width(), panel_height_, kViewFrameColour);
    if (view.horizontal_axis == 0) {  // the wall plane, seen edge on
      draw_line(out_, view.x_of(wall_u(z_top_)), view.top, view.x_of(wall_u(z_low_)), bottom, {kWallColour, 3, ""},
                "wall");
    }
    // The finishing height is measured along the wall: drawn at the world height where
    // the wall reaches it.
    const double finish = view.top + (z_top_ - finish_world_z()) * view.scale;
    draw_line(out_, view.left, finish, view.left + view.width(), finish, kFinishStroke, "finish");
    write_holds(view);
    write_body(view);
    write_grasp_spheres(view);
    if (options_.loads != nullptr) write_loads(view, *options_.loads);
    if (options_.hold_forces != nullptr) write_hold_forces(view, *options_.hold_forces);
    out_ += "</g>\n";
  }

  void write_holds(const View& view) {
    append_format(out_, "<g class=\"holds\" fill=\"{}\">\n", kHoldBesideBodyColour);
    for (const Hold& hold : holds_) {
      const Point c = view.project(hold.position);
      append_format(out_, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\"/>\n", c[0], c[1],
                    std::max(1.5, hold.radius * view.scale));
    }
    out_ += "</g>\n";
  }

  // Painter's algorithm: the primitives furthest from the viewer first.
  void write_body(const View& view) {
    std::vector<const PlacedVisual*> order;
    for (const PlacedVisual& v : visuals_) order.push_back(&v);
    // Ties keep the model's order (std::sort with the index, not std::stable_sort, whose
    // temporary buffer libstdc++ 12 frees in a way ASan reports as a mismatch).
    std::sort(order.begin(), order.end(), [&](const PlacedVisual* a, const PlacedVisual* b) {
      const double depth_a = view.depth(a->centre), depth_b = view.depth(b->centre);
      return depth_a != depth_b ? depth_a < depth_b : a < b;
    });
    out_ += "<g class=\"body\" stroke-width=\"0.8\" stroke-linejoin=\"round\">\n";
    for (const PlacedVisual* v : order) {
      const std::string fill = colour(v->visual->rgba, 1.0), stroke = colour(v->visual->rgba, 0.55);
      if (v->outline.empty()) {
        const Point c = view.project(v->centre);
        append_format(out_, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"{}\" stroke=\"{}\"/>\n", c[0],
                      c[1], v->visual->size.x() * view.scale, fill, stroke);
        continue;
      }
      std::vector<Point> points;
      for (const Eigen::Vector3d& p : v->outline) points.push_back(view.project(p));
      append_format(out_, "<polygon fill=\"{}\" stroke=\"{}\" points=\"", fill, stroke);
      const std::vector<Point> hull = convex_hull(std::move(points));
      for (std::size_t i = 0; i < hull.size(); ++i)
        append_format(out_, "{}{:.2f},{:.2f}", i == 0 ? "" : " ", hull[i][0], hull[i][1]);
      out_ += "\"/>\n";
    }
    out_ += "</g>\n";
  }

  void write_grasp_spheres(const View& view) {
    out_ += "<g class=\"grasp-spheres\" fill-opacity=\"0.35\" stroke-width=\"1.5\">\n";
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const Point c = view.project(grasp_point(limb));
      // data-limb names the limb for tools and for the browser test that compares sides with the replay.
      append_format(out_,
                    "<circle data-limb=\"{4}\" cx=\"{0:.2f}\" cy=\"{1:.2f}\" r=\"{2:.2f}\" fill=\"{3}\" "
                    "stroke=\"{3}\"/>\n",
                    c[0], c[1], options_.grasp_radius * view.scale, kLimbStyles[limb].colour, kLimbStyles[limb].code);
    }
    out_ += "</g>\n";
  }

  // The joints' torque ratios as dots, then the contact forces as arrows over them.
  void write_loads(const View& view, const StanceLoads& loads) {
    out_ += "<g class=\"joint-torques\" stroke=\"#333333\" stroke-width=\"0.6\">\n";
    for (const auto& [joint, ratio] : loads.joint_ratios) {
      const Eigen::Vector3d origin = tilt_ * data_.placements[joint].origin;
      const Point c = view.project(origin);
      append_format(
          out_, "<circle data-joint=\"{}\" data-ratio=\"{:.3f}\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\"/>\n",
          xml_escaped(model_.joints[joint].name), ratio, c[0], c[1], torque_ratio_colour(ratio));
    }
    out_ += "</g>\n<g class=\"contact-forces\">\n";
    for (int limb = 0; limb < kLimbCount; ++limb) {
      if (!loads.held[limb] || !loads.balanced) continue;
      const Eigen::Vector3d from = grasp_point(limb);
      const Eigen::Vector3d to = from + tilt_ * loads.forces[limb] * kMetresPerNewton;
      write_arrow(view.project(from), view.project(to), kLimbStyles[limb].code, loads.forces[limb].norm());
    }
    out_ += "</g>\n";
  }

  void write_hold_forces(const View& view, const std::array<Eigen::Vector3d, kLimbCount>& forces) {
    out_ += "<g class=\"hold-forces\">\n";
    for (int limb = 0; limb < kLimbCount; ++limb) {
      if (forces[limb].isZero()) continue;
      const Eigen::Vector3d from = grasp_point(limb);
      const Eigen::Vector3d to = from + tilt_ * forces[limb] * kMetresPerNewton;
      write_arrow(view.project(from), view.project(to), kLimbStyles[limb].code, forces[limb].norm());
    }
    out_ += "</g>\n";
  }

  // A line and its head (6 pixels long), the line naming the limb and the force for tools.
  void write_arrow(const Point& from, const Point& to, const char* limb, double newtons) {
    append_format(out_,
                  "<line data-limb=\"{}\" data-newtons=\"{:.1f}\" x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" "
                  "y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"2\"/>\n",
                  limb, newtons, from[0], from[1], to[0], to[1], kForceColour);
    const double dx = to[0] - from[0], dy = to[1] - from[1], length = std::hypot(dx, dy);
    if (length < 1e-9) return;
    const double ux = dx / length, uy = dy / length;
    append_format(out_, "<polygon fill=\"{}\" points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\"/>\n", kForceColour,
                  to[0], to[1], to[0] - 6 * ux - 3 * uy, to[1] - 6 * uy + 3 * ux, to[0] - 6 * ux + 3 * uy,
                  to[1] - 6 * uy - 3 * ux);
  }

  // A force arrow's legend key.
  static void draw_force_key(std::string& svg, double x, double y) {
    append_format(svg,
                  "<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" stroke=\"{}\" stroke-width=\"2\"/>\n",
                  x, y, x + 24, y, kForceColour);
  }

  // A hold, each limb's grasp sphere, the finishing height.
  std::vector<LegendItem> legend_items() const {
    std::vector<LegendItem> items{{"hold", [](std::string& svg, double x, double y) {
                                     append_format(svg, "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"{}\"/>\n",
                                                   x + 12, y, kHoldBesideBodyColour);
                                   }}};
    for (const LimbStyle& style : kLimbStyles) {
      items.push_back({fmt::format("{} grasp sphere", style.name), [&style](std::string& svg, double x, double y) {
                         append_format(
                             svg,
                             "<circle cx=\"{0:.2f}\" cy=\"{1:.2f}\" r=\"6\" fill=\"{2}\" fill-opacity=\"0.35\" "
                             "stroke=\"{2}\" stroke-width=\"1.5\"/>\n",
                             x + 12, y, style.colour);
                       }});
    }
    if (options_.loads != nullptr) {
      items.push_back({"contact force, 0.1 m per 100 N", draw_force_key});
      for (const double ratio : {0.0, 0.5, 1.0}) {
        items.push_back(
            {fmt::format("joint torque {:g} x its limit", ratio), [ratio](std::string& svg, double x, double y) {
               append_format(svg,
                             "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\" stroke=\"#333333\" "
                             "stroke-width=\"0.6\"/>\n",
                             x + 12, y, torque_ratio_colour(ratio));
             }});
      }
    }
    if (options_.hold_forces != nullptr) {
      items.push_back({"force from the hold in MuJoCo, 0.1 m per 100 N", draw_force_key});
    }
    items.push_back({fmt::format("finish height, {:.2f} m{}", wall_.finish_height,
                                 wall_.incline_deg != 0.0 ? " along the wall" : ""),
                     [](std::string& svg, double x, double y) { draw_line(svg, x, y, x + 24, y, kFinishStroke); }});
    return items;
  }

  const BodyModel& model_;
  const Wall& wall_;
  const BodySvgOptions& options_;
  BodyData data_;
  std::vector<PlacedVisual> visuals_;
  std::vector<Hold> holds_;  // the wall's, turned to the world when it is inclined
  Eigen::Matrix3d tilt_ = Eigen::Matrix3d::Identity();
  std::array<View, 2> views_{};
  double z_low_ = 0, z_top_ = 0, panel_height_ = 0, width_ = 0, height_ = 0;
  double tick_spacing_ = 0;
  std::vector<LegendItem> legend_;
  std::vector<LegendPlace> legend_places_;
  std::string out_;
};

}  // namespace

std::string torque_ratio_colour(double ratio) {
  // Green (26, 152, 80) to yellow (254, 224, 139) to red (215, 48, 39), as ColorBrewer's RdYlGn.
  constexpr std::array<std::array<double, 3>, 3> stops{{{26, 152, 80}, {254, 224, 139}, {215, 48, 39}}};
  const double t = std::clamp(std::isfinite(ratio) ? ratio : 1.0, 0.0, 1.0) * 2.0;
  const int segment = std::min(static_cast<int>(t), 1);
  const double f = t - segment;
  std::array<int, 3> rgb{};
  for (int c = 0; c < 3; ++c) {
    rgb[c] = static_cast<int>(std::lround((1 - f) * stops[segment][c] + f * stops[segment + 1][c]));
  }
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

std::string render_body_svg(const BodyModel& model, const Posture& posture, const Wall& wall,
                            const BodySvgOptions& options) {
  if (!(options.pixels_per_metre > 0) || !std::isfinite(options.pixels_per_metre)) {
    throw std::invalid_argument(
        fmt::format("render_body_svg: pixels_per_metre must be positive, not {}", options.pixels_per_metre));
  }
  return BodyFigure(model, posture, wall, options).render();
}

}  // namespace crux
