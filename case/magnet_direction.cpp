#include "case/magnet_direction.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace rheomag::cases {
namespace {

// The functions of FEMM's Lua math library that muparser lacks (angles in radians, as FEMM's).
double lua_atan2(double y, double x) {
  return std::atan2(y, x);
}
double lua_mod(double a, double b) {
  return std::fmod(a, b);
}
double lua_floor(double a) {
  return std::floor(a);
}
double lua_ceil(double a) {
  return std::ceil(a);
}
double lua_deg(double a) {
  return a * 180.0 / std::numbers::pi;
}
double lua_rad(double a) {
  return a * std::numbers::pi / 180.0;
}

}  // namespace

/// The compiled expression and the variables it reads.
struct MagnetDirectionField::Parser {
  mu::Parser parser;
  double x = 0, y = 0, theta = 0, radius = 0;
};

MagnetDirectionField::MagnetDirectionField(const MagnetDirection& direction,
                                           const std::string& where)
    : direction_(direction), where_(where) {
  if (direction.expression.empty()) return;
  parser_ = std::make_unique<Parser>();
  try {
    mu::Parser& p = parser_->parser;
    for (const char* name : {"x", "r"}) p.DefineVar(name, &parser_->x);
    for (const char* name : {"y", "z"}) p.DefineVar(name, &parser_->y);
    p.DefineVar("theta", &parser_->theta);
    p.DefineVar("R", &parser_->radius);
    p.DefineConst("pi", std::numbers::pi);
    p.DefineFun("atan2", lua_atan2);
    p.DefineFun("mod", lua_mod);
    p.DefineFun("floor", lua_floor);
    p.DefineFun("ceil", lua_ceil);
    p.DefineFun("deg", lua_deg);
    p.DefineFun("rad", lua_rad);
    p.SetExpr(direction.expression);
    p.Eval();  // parses now: unknown names and syntax errors are input errors of the file
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(where + ": magnetisation direction expression '" + direction.expression +
                     "': " + e.GetMsg());
  }
}

MagnetDirectionField::~MagnetDirectionField() = default;
MagnetDirectionField::MagnetDirectionField(MagnetDirectionField&&) noexcept = default;
MagnetDirectionField& MagnetDirectionField::operator=(MagnetDirectionField&&) noexcept = default;

double MagnetDirectionField::degrees_at(mesh::Point p) const {
  if (!parser_) return direction_.degrees;
  parser_->x = p.r / direction_.length_unit;
  parser_->y = p.z / direction_.length_unit;
  parser_->theta = std::atan2(parser_->y, parser_->x) * 180.0 / std::numbers::pi;
  parser_->radius = std::hypot(parser_->x, parser_->y);
  double value = 0.0;
  try {
    value = parser_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(where_ + ": magnetisation direction expression '" + direction_.expression +
                     "': " + e.GetMsg());
  }
  if (!std::isfinite(value))
    throw InputError(where_ + ": magnetisation direction expression '" + direction_.expression +
                     "' is not a finite number at (" + std::to_string(parser_->x) + ", " +
                     std::to_string(parser_->y) + ")");
  return value;
}

}  // namespace rheomag::cases
