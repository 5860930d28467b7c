// `coupon:` section; see coupon_reader.hpp. Also the smooth velocity ramp of the loading blocks.
#include "config/coupon_reader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace plyimpact::config {

CurveSpec smooth_ramp_curve(double velocity, double ramp, int segments) {
  if (!(ramp > 0)) return CurveSpec{{0.0}, {velocity}};
  CurveSpec c;
  for (int i = 0; i <= segments; ++i) {
    const double t = ramp * i / segments;
    c.t.push_back(t);
    c.y.push_back(velocity * 0.5 * (1 - std::cos(std::numbers::pi * i / segments)));
  }
  return c;
}

namespace detail {
namespace {

namespace u = units;

std::vector<std::string> node_set_names(const Scene& scene) {
  std::vector<std::string> out;
  for (const auto& s : scene.node_sets) out.push_back(s.name);
  return out;
}

int read_coupon_axis(const Reader& r) {
  const std::string a = r.as_choice({"x", "y", "z"});
  return a == "x" ? 0 : a == "y" ? 1 : 2;
}

// The 1-based interface must exist and hold a tiebreak law: its damage front is the crack.
int read_interface(const Reader& r, const Scene& scene) {
  const LaminateSpec& lam = *scene.laminate;
  const int n = int(lam.interface_law.size());
  std::vector<int> with_law;
  for (int i = 0; i < n; ++i)
    if (lam.interface_law[i]) with_law.push_back(i + 1);
  std::string allowed = "the number of an interface with a tiebreak law (laminate.interfaces): ";
  for (std::size_t i = 0; i < with_law.size(); ++i) allowed += (i ? ", " : "") + std::to_string(with_law[i]);
  if (with_law.empty()) allowed += "none in this scene";
  const long k = r.as_integer();
  if (std::find(with_law.begin(), with_law.end(), int(k)) == with_law.end())
    r.fail(msg() << "interface " << k << " has no tiebreak law", allowed);
  return int(k);
}

bool has_velocity_on(const Scene& scene, const std::string& set, int axis) {
  return std::any_of(scene.boundary_conditions.begin(), scene.boundary_conditions.end(), [&](const auto& bc) {
    return bc.node_set == set && bc.kind == BoundaryConditionSpec::Kind::Velocity && bc.dofs[axis];
  });
}

}  // namespace

CouponSpec read_coupon(const Reader& r, const Scene& scene) {
  const char* shape =
      "{type: DCB | ENF | MMB, interface: <number>, load: <node set>, opening: {upper: <node set>, lower: <node set>}, "
      "optional axis: z, crack_origin: <x of the load line>}";
  r.require_map(shape);
  r.allow_keys({"type", "interface", "load", "opening", "axis", "crack_origin"});
  if (!scene.laminate)
    r.fail("a coupon needs a laminate section (its interface is the crack plane), and this scene has none",
           "coupon together with laminate: {..., interfaces: {model: tiebreak, ...}}");
  CouponSpec c;
  c.where = r.where();
  const std::string type = r.at("type", "DCB, ENF or MMB").as_choice({"DCB", "ENF", "MMB"});
  c.type = type == "DCB" ? CouponSpec::Type::DCB : type == "ENF" ? CouponSpec::Type::ENF : CouponSpec::Type::MMB;
  c.interface = read_interface(r.at("interface", "the number of the delaminating interface"), scene);
  if (const auto a = r.find("axis")) c.axis = read_coupon_axis(*a);
  const auto sets = node_set_names(scene);
  c.load = r.reference("load", sets, "node set", "node_sets");
  if (!has_velocity_on(scene, c.load, c.axis))
    r.at("load", "").fail(msg() << "node set '" << c.load << "' has no prescribed velocity along "
                                << "xyz"[c.axis] << ", so it carries no reaction to measure",
                          "a node set loaded by boundary_conditions: {node_set, velocity: {dofs: [...], value, ramp}}");
  const Reader o = r.at("opening", "{upper: <node set>, lower: <node set>} (one side may be left out: the ground)");
  o.require_map("{upper: <node set>, lower: <node set>}");
  o.allow_keys({"upper", "lower"});
  if (o.has("upper")) c.upper = o.reference("upper", sets, "node set", "node_sets");
  if (o.has("lower")) c.lower = o.reference("lower", sets, "node set", "node_sets");
  if (c.upper.empty() && c.lower.empty())
    o.fail("no node set given", "upper, lower or both (the opening is upper minus lower along the axis)");
  if (c.load != c.upper && c.load != c.lower)
    r.at("load", "").fail(msg() << "the load set '" << c.load << "' is neither opening.upper nor opening.lower",
                          "the upper or the lower loading block, so the load's sign follows the opening");
  const double length = scene.laminate->length;
  c.crack_origin = r.quantity_or("crack_origin", u::length, 0.0,
                                 Limits::interval(0, false, length, false, "the load line's x"));
  return c;
}

}  // namespace detail
}  // namespace plyimpact::config
