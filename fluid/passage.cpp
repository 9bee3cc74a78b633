// Unmagnetised passages: the laminar Newtonian formulas of newtonian.hpp (Hagen-Poiseuille
// pipe, exact annulus of Bird, Stewart & Lightfoot eq. 2.4-17, plane Poiseuille slit, radial
// disk) and minor losses K rho V^2 / 2 (e.g. Idelchik, Handbook of Hydraulic Resistance).

#include "fluid/passage.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "fluid/gap.hpp"
#include "fluid/newtonian.hpp"

namespace rheomag::fluid {

std::string shape_name(PassageShape shape) {
  switch (shape) {
    case PassageShape::pipe:
      return "pipe";
    case PassageShape::annulus:
      return "annulus";
    case PassageShape::slit:
      return "slit";
    case PassageShape::radial:
      return "radial";
  }
  return "pipe";
}

std::vector<Passage> read_passages(const cases::TomlSection& valve) {
  std::vector<Passage> passages;
  for (const auto& t : valve.table_array("passage")) {
    t.allow_only({"name", "shape", "region", "diameter", "inner_radius", "outer_radius", "gap",
                  "width", "length"});
    Passage p;
    p.name = t.required_string("name");
    const std::string shape = t.required_string("shape");
    if (shape == "pipe")
      p.shape = PassageShape::pipe;
    else if (shape == "annulus")
      p.shape = PassageShape::annulus;
    else if (shape == "slit")
      p.shape = PassageShape::slit;
    else if (shape == "radial")
      p.shape = PassageShape::radial;
    else
      t.fail("shape", "\"" + shape + "\": expected \"pipe\", \"annulus\", \"slit\" or \"radial\"");
    p.region = t.string("region").value_or("");
    if (!p.region.empty()) {
      for (const char* key : {"diameter", "inner_radius", "outer_radius", "gap", "length"})
        if (t.has(key)) t.fail(key, "give the dimensions or region, not both");
      if (p.shape == PassageShape::slit)
        t.fail("region", "a slit's dimensions cannot come from an axisymmetric region");
    } else {
      p.diameter = t.non_negative_or("diameter", 0.0);
      p.inner_radius = t.non_negative_or("inner_radius", 0.0);
      p.outer_radius = t.non_negative_or("outer_radius", 0.0);
      p.gap = t.non_negative_or("gap", 0.0);
      p.length = t.non_negative_or("length", 0.0);
    }
    p.width = t.non_negative_or("width", 0.0);
    if (p.region.empty()) {
      try {
        validate(p);
      } catch (const InputError& e) {
        t.fail("shape", e.what());
      }
    }
    passages.push_back(std::move(p));
  }
  return passages;
}

std::vector<MinorLoss> read_losses(const cases::TomlSection& valve) {
  std::vector<MinorLoss> losses;
  for (const auto& t : valve.table_array("loss")) {
    t.allow_only({"name", "k", "section", "area", "radius"});
    MinorLoss loss;
    loss.name = t.required_string("name");
    loss.k = t.non_negative_or("k", -1.0);
    if (loss.k < 0.0) t.fail("k", "the loss coefficient K (>= 0) is required");
    loss.section = t.string("section").value_or("");
    loss.area = t.non_negative_or("area", 0.0);
    loss.radius = t.non_negative_or("radius", 0.0);
    if (loss.section.empty() == !(loss.area > 0.0))
      t.fail("section", "give either section = \"<gap or passage name>\" or area (m^2) > 0");
    losses.push_back(std::move(loss));
  }
  return losses;
}

void validate(const Passage& p) {
  const std::string what = "passage \"" + p.name + "\" (" + shape_name(p.shape) + ")";
  auto need = [&](double value, const char* key) {
    if (!(value > 0.0 && std::isfinite(value)))
      throw InputError(what + ": " + key + " must be > 0 m");
  };
  switch (p.shape) {
    case PassageShape::pipe:
      need(p.diameter, "diameter");
      need(p.length, "length");
      break;
    case PassageShape::annulus:
    case PassageShape::radial:
      if (p.shape == PassageShape::annulus) need(p.length, "length");
      if (p.shape == PassageShape::radial) need(p.gap, "gap");
      need(p.inner_radius, "inner_radius");
      if (!(p.outer_radius > p.inner_radius))
        throw InputError(what + ": outer_radius must be > inner_radius");
      break;
    case PassageShape::slit:
      need(p.gap, "gap");
      need(p.width, "width");
      need(p.length, "length");
      break;
  }
}

double passage_dp(const Passage& p, double viscosity, double flow) {
  validate(p);
  switch (p.shape) {
    case PassageShape::pipe:
      return pipe_poiseuille_dp(p.diameter, p.length, viscosity, flow);
    case PassageShape::annulus:
      return annulus_poiseuille_dp(
          AnnulusGeometry{p.outer_radius - p.inner_radius, 0.5 * (p.inner_radius + p.outer_radius),
                          p.length},
          viscosity, flow);
    case PassageShape::slit:
      return slit_poiseuille_dp(SlitGeometry{p.gap, p.width, p.length}, viscosity, flow);
    case PassageShape::radial:
      return radial_poiseuille_dp(RadialGeometry{p.gap, p.inner_radius, p.outer_radius}, viscosity,
                                  flow);
  }
  return 0.0;
}

double passage_area(const Passage& p, double radius) {
  validate(p);
  switch (p.shape) {
    case PassageShape::pipe:
      return std::numbers::pi * p.diameter * p.diameter / 4.0;
    case PassageShape::annulus:
      return std::numbers::pi * (p.outer_radius * p.outer_radius - p.inner_radius * p.inner_radius);
    case PassageShape::slit:
      return p.gap * p.width;
    case PassageShape::radial:
      if (!(radius >= p.inner_radius && radius <= p.outer_radius))
        throw InputError("passage \"" + p.name +
                         "\" (radial): a loss in it needs radius within inner_radius.."
                         "outer_radius");
      return 2.0 * std::numbers::pi * radius * p.gap;
  }
  return 0.0;
}

double hydraulic_diameter(const Passage& p) {
  validate(p);
  switch (p.shape) {
    case PassageShape::pipe:
      return p.diameter;
    case PassageShape::annulus:
      return 2.0 * (p.outer_radius - p.inner_radius);
    case PassageShape::slit:
      return 2.0 * p.gap * p.width / (p.gap + p.width);
    case PassageShape::radial:
      return 2.0 * p.gap;
  }
  return 0.0;
}

}  // namespace rheomag::fluid
