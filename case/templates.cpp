// The parametric device templates (three valves, a damper piston, a disc brake). Every default
// dimension is documented in the reference case files (cases/*.toml) with its reason; the geometry
// is axisymmetric, z along the valve axis.

#include "case/templates.hpp"

#include <map>

#include "core/error.hpp"

namespace rheomag::cases {
namespace {

using mesh::GapKind;
using mesh::Point;

constexpr double mm = 1e-3;

RegionOutline rect(std::string name, std::string material, double r0, double r1, double z0,
                   double z1) {
  RegionOutline region;
  region.name = std::move(name);
  region.material = std::move(material);
  region.outline = {{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
  return region;
}

RegionOutline polygon(std::string name, std::string material, std::vector<Point> points) {
  RegionOutline region;
  region.name = std::move(name);
  region.material = std::move(material);
  region.outline = std::move(points);
  return region;
}

RegionOutline gap(RegionOutline region, GapKind kind) {
  region.gap = kind;
  return region;
}

/// Throws InputError when a derived dimension is not positive.
void require_positive(const TemplateValues& v, double value, const std::string& what) {
  if (!(value > 0.0))
    throw InputError(v.where + ": inconsistent dimensions: " + what + " = " +
                     std::to_string(value / mm) + " mm must be positive");
}

std::vector<RegionOutline> finish(std::vector<RegionOutline> regions, const TemplateValues& v) {
  for (RegionOutline& region : regions) region.where = v.where + " (template region)";
  return regions;
}

// ---------------------------------------------------------------------------------------------
// annular_valve: a steel core with a coil groove (coil on an aluminium bobbin) inside a steel
// ring (the "disk"); the fluid flows axially through the annular channel between them and is
// magnetised where the core's two poles face the ring: gap_top and gap_bottom, each
// pole_length long (effective length L = 2 pole_length).
std::vector<RegionOutline> build_annular(const TemplateValues& v) {
  const double r1 = v["gap_radius"] - 0.5 * v["gap_width"];  // core surface
  const double r2 = v["gap_radius"] + 0.5 * v["gap_width"];  // ring bore
  const double rn = v["neck_radius"];
  const double wall = v["bobbin_wall"];
  const double cover = v["cover_thickness"];
  const double zg = 0.5 * v["coil_length"] + wall;  // groove half length
  const double zt = zg + v["pole_length"];          // core half length
  const double rc = r1 - cover;                     // coil outer radius
  require_positive(v, r1, "gap_radius - gap_width/2 (core radius)");
  require_positive(v, rc - wall - rn,
                   "coil depth = gap_radius - gap_width/2 - cover_thickness - bobbin_wall - "
                   "neck_radius");
  const std::string steel = v.text("core_material");
  const std::string fluid = v.text("fluid_material");
  std::vector<RegionOutline> regions;
  regions.push_back(
      polygon("core", steel,
              {{0, -zt}, {r1, -zt}, {r1, -zg}, {rn, -zg}, {rn, zg}, {r1, zg}, {r1, zt}, {0, zt}}));
  regions.push_back(polygon("bobbin", v.text("bobbin_material"),
                            {{rn, -zg},
                             {rc, -zg},
                             {rc, -zg + wall},
                             {rn + wall, -zg + wall},
                             {rn + wall, zg - wall},
                             {rc, zg - wall},
                             {rc, zg},
                             {rn, zg}}));
  regions.push_back(rect("bobbin_cover", v.text("bobbin_material"), rc, r1, -zg, zg));
  RegionOutline coil = rect("coil", v.text("coil_material"), rn + wall, rc, -zg + wall, zg - wall);
  coil.circuit = v.text("circuit");
  coil.turns = v["turns"];
  regions.push_back(coil);
  regions.push_back(gap(rect("gap_top", fluid, r1, r2, zg, zt), GapKind::annular));
  regions.push_back(gap(rect("gap_bottom", fluid, r1, r2, -zt, -zg), GapKind::annular));
  regions.push_back(rect("channel", fluid, r1, r2, -zg, zg));
  regions.push_back(rect("disk", v.text("disk_material"), r2, r2 + v["disk_thickness"], -zt, zt));
  return finish(std::move(regions), v);
}

// ---------------------------------------------------------------------------------------------
// radial_valve: a pot core (central post, bottom plate and shell in one steel part) holding the
// coil, closed by a steel cover plate; the fluid enters through a port on the axis and flows
// radially outward through the disc-shaped gap between pot and cover. It is magnetised where
// the post (gap_inner) and the shell (gap_outer) face the cover.
std::vector<RegionOutline> build_radial(const TemplateValues& v) {
  const double rc = v["post_radius"];
  const double wall = v["bobbin_wall"];
  const double r_in = rc + wall + v["coil_depth"];  // shell bore
  const double r_out = r_in + v["shell_thickness"];
  const double g = v["gap_width"];
  const double zb = -(v["coil_length"] + 2 * wall);  // cavity bottom
  const double z_bottom = zb - v["plate_thickness"];
  const double rp = v["port_radius"];
  const double z_cover = g + v["plate_thickness"];
  if (!(rp < rc))
    throw InputError(v.where + ": inconsistent dimensions: port_radius must be below post_radius");
  const std::string steel = v.text("core_material");
  const std::string fluid = v.text("fluid_material");
  std::vector<RegionOutline> regions;
  regions.push_back(polygon("pot", steel,
                            {{0, z_bottom},
                             {r_out, z_bottom},
                             {r_out, 0},
                             {r_in, 0},
                             {r_in, zb},
                             {rc, zb},
                             {rc, 0},
                             {0, 0}}));
  regions.push_back(polygon("bobbin", v.text("bobbin_material"),
                            {{rc, zb},
                             {r_in, zb},
                             {r_in, zb + wall},
                             {rc + wall, zb + wall},
                             {rc + wall, -wall},
                             {r_in, -wall},
                             {r_in, 0},
                             {rc, 0}}));
  RegionOutline coil = rect("coil", v.text("coil_material"), rc + wall, r_in, zb + wall, -wall);
  coil.circuit = v.text("circuit");
  coil.turns = v["turns"];
  regions.push_back(coil);
  regions.push_back(gap(rect("gap_inner", fluid, 0, rc, 0, g), GapKind::radial));
  regions.push_back(rect("channel", fluid, rc, r_in, 0, g));
  regions.push_back(gap(rect("gap_outer", fluid, r_in, r_out, 0, g), GapKind::radial));
  regions.push_back(rect("port", fluid, 0, rp, g, z_cover));
  regions.push_back(rect("cover", v.text("cover_material"), rp, r_out, g, z_cover));
  return finish(std::move(regions), v);
}

// ---------------------------------------------------------------------------------------------
// meandering_valve: after Imaduddin et al. (JIMSS 26 (2015) 1038): the fluid enters on the axis,
// flows outward through a radial gap over the steel core, down an annular gap between the core
// and a steel lip of the casing, along a non-magnetic spacer, then through the mirrored annular
// and radial gaps to the outlet on the axis. The coil sits in the casing around the core; the
// flux crosses the radial and annular gaps at both ends (magnetically in parallel, hydraulically
// in series).
std::vector<RegionOutline> build_meandering(const TemplateValues& v) {
  const double rc = v["core_radius"];
  const double zc = 0.5 * v["core_length"];
  const double ga = v["annular_gap_width"];
  const double gr = v["radial_gap_width"];
  const double la = v["annular_gap_length"];
  const double tl = v["lip_thickness"];
  const double rp = v["port_radius"];
  const double wall = v["bobbin_wall"];
  const double zh = zc + gr;  // plate inner face
  const double z_top = zh + v["plate_thickness"];
  const double rl = rc + ga;  // lip bore
  const double rw = rl + tl;  // winding space inner radius
  const double r_in = rw + wall + v["coil_depth"];
  const double r_out = r_in + v["shell_thickness"];
  if (!(rp < rc))
    throw InputError(v.where + ": inconsistent dimensions: port_radius must be below core_radius");
  require_positive(v, zc - la, "core_length/2 - annular_gap_length (spacer half length)");
  require_positive(v, zh - 2 * wall,
                   "coil length (core_length + 2 radial_gap_width - 4 bobbin_wall)");
  const std::string steel = v.text("core_material");
  const std::string fluid = v.text("fluid_material");
  std::vector<RegionOutline> regions;
  regions.push_back(rect("core", steel, 0, rc, -zc, zc));
  regions.push_back(polygon("casing", v.text("casing_material"),
                            {{rp, z_top},
                             {rp, zh},
                             {rl, zh},
                             {rl, zc - la},
                             {rw, zc - la},
                             {rw, zh},
                             {r_in, zh},
                             {r_in, -zh},
                             {rw, -zh},
                             {rw, -zc + la},
                             {rl, -zc + la},
                             {rl, -zh},
                             {rp, -zh},
                             {rp, -z_top},
                             {r_out, -z_top},
                             {r_out, z_top}}));
  regions.push_back(rect("spacer", v.text("spacer_material"), rl, rw, -zc + la, zc - la));
  regions.push_back(polygon("bobbin", v.text("bobbin_material"),
                            {{rw, -zh},
                             {r_in, -zh},
                             {r_in, -zh + wall},
                             {rw + wall, -zh + wall},
                             {rw + wall, zh - wall},
                             {r_in, zh - wall},
                             {r_in, zh},
                             {rw, zh}}));
  RegionOutline coil =
      rect("coil", v.text("coil_material"), rw + wall, r_in, -zh + wall, zh - wall);
  coil.circuit = v.text("circuit");
  coil.turns = v["turns"];
  regions.push_back(coil);
  regions.push_back(rect("port_top", fluid, 0, rp, zc, z_top));
  regions.push_back(gap(rect("radial_gap_top", fluid, rp, rc, zc, zh), GapKind::radial));
  regions.push_back(gap(rect("annular_gap_top", fluid, rc, rl, zc - la, zh), GapKind::annular));
  regions.push_back(rect("channel", fluid, rc, rl, -zc + la, zc - la));
  regions.push_back(
      gap(rect("annular_gap_bottom", fluid, rc, rl, -zh, -zc + la), GapKind::annular));
  regions.push_back(gap(rect("radial_gap_bottom", fluid, rp, rc, -zh, -zc), GapKind::radial));
  regions.push_back(rect("port_bottom", fluid, 0, rp, -z_top, -zc));
  return finish(std::move(regions), v);
}

// damper_piston: the annular_valve's core, coil and poles as a damper's piston head sliding in
// a steel tube (the template's "disk" is the tube wall): the whole annulus between piston and
// tube is a gap (gap_top, gap_coil, gap_bottom), since the piston drags the fluid along all of
// it (mixed mode, valve/damper.hpp), not only where the poles magnetise it.
std::vector<RegionOutline> build_piston(const TemplateValues& v) {
  std::vector<RegionOutline> regions = build_annular(v);
  for (RegionOutline& region : regions) {
    if (region.name == "channel") {
      region.name = "gap_coil";
      region.gap = GapKind::annular;
    }
    if (region.name == "disk") region.name = "tube";
  }
  return regions;
}

// ---------------------------------------------------------------------------------------------
// disc_brake: a steel shear plate (disc) on a non-magnetic shaft turns between the two steel
// side plates of a housing; the coil sits in the plane of the disc beyond its rim and a steel
// outer ring closes the flux path (the layout of paper 002's rotary damper). The flux crosses
// the two fluid gaps (gap_top, gap_bottom: radial, one sheared face each) in series.
std::vector<RegionOutline> build_disc_brake(const TemplateValues& v) {
  const double rs = v["shaft_radius"];
  const double rd = v["disc_radius"];
  const double t2 = 0.5 * v["disc_thickness"];
  const double zg = t2 + v["gap_width"];        // side plates' inner faces
  const double zp = zg + v["plate_thickness"];  // outer faces
  const double rci = rd + v["rim_clearance"];   // coil inner radius
  const double rco = rci + v["coil_depth"];     // coil outer radius = ring bore
  const double rr = rco + v["ring_thickness"];  // housing outer radius
  if (!(rs < rd))
    throw InputError(v.where + ": inconsistent dimensions: shaft_radius must be below disc_radius");
  const std::string steel = v.text("housing_material");
  const std::string fluid = v.text("fluid_material");
  std::vector<RegionOutline> regions;
  regions.push_back(rect("shaft", v.text("shaft_material"), 0, rs, -zp, zp));
  regions.push_back(rect("disc", v.text("disc_material"), rs, rd, -t2, t2));
  regions.push_back(gap(rect("gap_top", fluid, rs, rd, t2, zg), GapKind::radial));
  regions.push_back(gap(rect("gap_bottom", fluid, rs, rd, -zg, -t2), GapKind::radial));
  regions.push_back(rect("rim_fluid", fluid, rd, rci, -zg, zg));
  RegionOutline coil = rect("coil", v.text("coil_material"), rci, rco, -zg, zg);
  coil.circuit = v.text("circuit");
  coil.turns = v["turns"];
  regions.push_back(coil);
  regions.push_back(rect("plate_top", steel, rs, rco, zg, zp));
  regions.push_back(rect("plate_bottom", steel, rs, rco, -zp, -zg));
  regions.push_back(rect("ring", steel, rco, rr, -zp, zp));
  return finish(std::move(regions), v);
}

TemplateParameter length(std::string key, double millimetres, std::string doc) {
  return {std::move(key), ParameterKind::length, millimetres * mm, "", std::move(doc)};
}
TemplateParameter wall(std::string key, double millimetres, std::string doc) {
  TemplateParameter p = length(std::move(key), millimetres, std::move(doc));
  p.role = ParameterRole::wall;
  return p;
}
TemplateParameter count(std::string key, double value, std::string doc) {
  return {std::move(key), ParameterKind::count, value, "", std::move(doc), ParameterRole::count};
}
TemplateParameter material(std::string key, std::string name, std::string doc) {
  return {std::move(key),  ParameterKind::material, 0.0,
          std::move(name), std::move(doc),          ParameterRole::choice};
}
TemplateParameter fluid_material(std::string name, std::string doc) {
  TemplateParameter p = material("fluid_material", std::move(name), std::move(doc));
  p.role = ParameterRole::fluid;
  return p;
}
TemplateParameter circuit() {
  return {"circuit",
          ParameterKind::name,
          0.0,
          "coil",
          "name of the [[circuit]] driving the coil",
          ParameterRole::choice};
}

std::vector<ValveTemplate> make_templates() {
  std::vector<ValveTemplate> list;
  list.push_back(
      {"annular_valve",
       "steel core with a coil groove inside a steel ring; two annular gaps at the poles",
       {length("gap_radius", 19.5, "mean radius of the annular channel (paper 000: R)"),
        length("gap_width", 1.0, "radial width of the annular channel (paper 000: d)"),
        wall("pole_length", 5.0, "axial length of each pole; L = 2 pole_length (paper 000: 10)"),
        length("neck_radius", 10.5, "radius of the core under the coil groove"),
        length("coil_length", 32.0, "axial length of the winding"),
        length("bobbin_wall", 1.0, "thickness of the bobbin hub and flanges"),
        length("cover_thickness", 0.5, "non-magnetic sleeve between coil and channel"),
        wall("disk_thickness", 5.0, "radial thickness of the steel ring (disk)"),
        count("turns", 600, "coil turns (paper 000: 600 turns AWG 24)"), circuit(),
        material("core_material", "AISI 1010", "core"),
        material("disk_material", "AISI 1010", "ring around the channel"),
        material("bobbin_material", "Aluminium 1100", "bobbin and sleeve"),
        material("coil_material", "Copper", "winding"),
        fluid_material("MRC-C1L", "MR fluid in the channel")},
       build_annular});
  list.push_back(
      {"radial_valve",
       "pot core with coil closed by a cover plate; a disc-shaped radial gap between them",
       {length("gap_width", 1.0, "axial width of the radial gap"),
        length("post_radius", 10.0, "radius of the central post"),
        length("coil_depth", 8.0, "radial depth of the winding"),
        length("coil_length", 16.0, "axial length of the winding"),
        length("bobbin_wall", 1.0, "thickness of the bobbin hub and flanges"),
        wall("shell_thickness", 3.0, "radial thickness of the pot's shell"),
        wall("plate_thickness", 6.0, "thickness of the pot bottom and of the cover plate"),
        length("port_radius", 3.0, "radius of the inlet port on the axis"),
        count("turns", 300, "coil turns"), circuit(),
        material("core_material", "AISI 1010", "pot core"),
        material("cover_material", "AISI 1010", "cover plate"),
        material("bobbin_material", "Aluminium 1100", "bobbin"),
        material("coil_material", "Copper", "winding"), fluid_material("MRF-132DG", "MR fluid")},
       build_radial});
  list.push_back(
      {"meandering_valve",
       "core in a steel casing with lips; radial + annular gaps at both ends in series",
       {length("annular_gap_width", 0.5, "annular gaps (paper 001: 0.5)"),
        length("radial_gap_width", 0.5, "radial gaps (paper 001: 0.5)"),
        length("core_radius", 12.0, "radius of the steel centre core"),
        length("core_length", 30.0, "axial length of the centre core"),
        length("annular_gap_length", 4.0, "axial length of each lip facing the core"),
        wall("lip_thickness", 3.0, "radial thickness of the casing lips"),
        length("port_radius", 3.0, "radius of the ports on the axis"),
        wall("plate_thickness", 5.0, "thickness of the casing end plates"),
        length("bobbin_wall", 1.0, "thickness of the bobbin hub and flanges"),
        length("coil_depth", 8.0, "radial depth of the winding"),
        wall("shell_thickness", 4.0, "radial thickness of the casing shell"),
        count("turns", 330, "coil turns"), circuit(),
        material("core_material", "AISI 1010", "centre core"),
        material("casing_material", "AISI 1010", "casing (paper 001: AISI 1010 mild steel)"),
        material("spacer_material", "Aluminium 1100", "spacer between the lips"),
        material("bobbin_material", "Aluminium 1100", "bobbin"),
        material("coil_material", "Copper", "winding"),
        fluid_material("MRF-132DG", "MR fluid (paper 001)")},
       build_meandering});
  // The piston reuses the annular valve's parameters with the defaults of
  // cases/damper_piston.toml and the ring read as the cylinder tube.
  std::vector<TemplateParameter> piston = list.front().parameters;
  for (TemplateParameter& p : piston) {
    const std::map<std::string, double> defaults = {{"pole_length", 6.0},
                                                    {"neck_radius", 12.0},
                                                    {"coil_length", 14.0},
                                                    {"disk_thickness", 4.0}};
    if (const auto it = defaults.find(p.key); it != defaults.end())
      p.default_number = it->second * mm;
    if (p.key == "turns") p.default_number = 300;
    if (p.key == "fluid_material") p.default_text = "MRF-132DG";
    if (p.key == "disk_thickness" || p.key == "disk_material")
      p.doc = "the cylinder tube around the piston";
    if (p.key == "gap_radius" || p.key == "gap_width")
      p.doc = "the annular gap between piston and tube";
  }
  list.push_back(
      {"damper_piston",
       "MR damper piston head in a steel tube: core, coil, two poles, the annular gap to the tube",
       std::move(piston), build_piston});
  list.push_back(
      {"disc_brake",
       "steel disc on a non-magnetic shaft between two steel side plates; rim coil, outer ring",
       {length("shaft_radius", 8.0, "radius of the non-magnetic shaft (disc and gaps start here)"),
        length("disc_radius", 40.0, "outer radius of the disc (and of the sheared gaps)"),
        wall("disc_thickness", 3.0, "axial thickness of the steel disc"),
        length("gap_width", 1.0, "axial width of each fluid gap"),
        length("rim_clearance", 2.0, "radial fluid space between the disc rim and the coil"),
        length("coil_depth", 12.0, "radial depth of the winding (its height: disc + 2 gaps)"),
        wall("plate_thickness", 5.5, "thickness of the housing's side plates"),
        wall("ring_thickness", 6.0, "radial thickness of the housing's outer ring"),
        count("turns", 200, "coil turns"), circuit(),
        material("shaft_material", "Aluminium 1100", "shaft"),
        material("disc_material", "AISI 1010", "disc (shear plate)"),
        material("housing_material", "AISI 1010", "side plates and outer ring"),
        material("coil_material", "Copper", "winding"), fluid_material("MRF-132DG", "MR fluid")},
       build_disc_brake});
  return list;
}

}  // namespace

std::string_view TemplateParameter::unit() const {
  switch (kind) {
    case ParameterKind::length:
      return "m";
    case ParameterKind::count:
      return "1";
    case ParameterKind::material:
    case ParameterKind::name:
      break;
  }
  return "";
}

std::vector<std::string> ValveTemplate::walls() const {
  std::vector<std::string> keys;
  for (const TemplateParameter& p : parameters)
    if (p.role == ParameterRole::wall) keys.push_back(p.key);
  return keys;
}

const std::vector<ValveTemplate>& valve_templates() {
  static const std::vector<ValveTemplate> list = make_templates();
  return list;
}

const ValveTemplate* find_template(const std::string& name) {
  for (const ValveTemplate& t : valve_templates())
    if (t.name == name) return &t;
  return nullptr;
}

TemplateValues default_values(const ValveTemplate& valve) {
  TemplateValues values;
  for (const TemplateParameter& p : valve.parameters) {
    if (p.kind == ParameterKind::length || p.kind == ParameterKind::count)
      values.numbers[p.key] = p.default_number;
    else
      values.texts[p.key] = p.default_text;
  }
  return values;
}

}  // namespace rheomag::cases
