#include "core/params.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace ll {

namespace {
std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
bool parseNumber(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}
}  // namespace

ParamDecl ParamDecl::integer(std::string name, int def, int min, int max, std::string help) {
  return {std::move(name), Type::Int, std::to_string(def), double(min), double(max), {}, std::move(help)};
}
ParamDecl ParamDecl::real(std::string name, double def, double min, double max, std::string help) {
  return {std::move(name), Type::Float, numberText(def), min, max, {}, std::move(help)};
}
ParamDecl ParamDecl::boolean(std::string name, bool def, std::string help) {
  return {std::move(name), Type::Bool, def ? "true" : "false", 0, 1, {}, std::move(help)};
}
ParamDecl ParamDecl::choice(std::string name, std::string def, std::vector<std::string> choices, std::string help) {
  return {std::move(name), Type::Choice, std::move(def), 0, 0, std::move(choices), std::move(help)};
}

std::string ParamDecl::typeName() const {
  switch (type) {
    case Type::Int: return "int";
    case Type::Float: return "float";
    case Type::Bool: return "bool";
    case Type::Choice: return "choice";
  }
  return "?";
}

std::string ParamDecl::rangeText() const {
  switch (type) {
    case Type::Int:
    case Type::Float: return "[" + numberText(min) + ", " + numberText(max) + "]";
    case Type::Bool: return "true or false";
    case Type::Choice: return "one of: " + joinNames(choices);
  }
  return "";
}

ParamSet::ParamSet(std::string owner, std::vector<ParamDecl> decls) : owner_(std::move(owner)), decls_(std::move(decls)) {
  for (const ParamDecl& d : decls_) values_[d.name] = d.defaultValue;
}

const ParamDecl& ParamSet::find(const std::string& name) const {
  for (const ParamDecl& d : decls_)
    if (d.name == name) return d;
  std::vector<std::string> names;
  for (const ParamDecl& d : decls_) names.push_back(d.name);
  throwUserError(owner_ + " has no parameter '" + name + "' (parameters: " +
                 (names.empty() ? std::string("none") : joinNames(names)) + ")");
}

bool ParamSet::has(const std::string& name) const { return values_.count(name) != 0; }

void ParamSet::set(const std::string& name, const std::string& value) {
  const ParamDecl& d = find(name);
  const std::string where = owner_ + " parameter '" + name + "'";
  double v = 0.0;
  switch (d.type) {
    case ParamDecl::Type::Int:
      if (!parseNumber(value, v) || v != std::floor(v))
        throwUserError(where + ": '" + value + "' is not an integer (range " + d.rangeText() + ")");
      [[fallthrough]];
    case ParamDecl::Type::Float:
      if (!parseNumber(value, v)) throwUserError(where + ": '" + value + "' is not a number (range " + d.rangeText() + ")");
      if (v < d.min || v > d.max) throwUserError(where + " = " + value + " is out of range " + d.rangeText());
      values_[name] = d.type == ParamDecl::Type::Int ? std::to_string(static_cast<long long>(v)) : numberText(v);
      return;
    case ParamDecl::Type::Bool:
      if (value != "true" && value != "false" && value != "1" && value != "0")
        throwUserError(where + ": '" + value + "' is not a boolean (allowed: true, false)");
      values_[name] = (value == "true" || value == "1") ? "true" : "false";
      return;
    case ParamDecl::Type::Choice:
      if (std::find(d.choices.begin(), d.choices.end(), value) == d.choices.end())
        throwUserError(where + ": unknown value '" + value + "' (" + d.rangeText() + ")");
      break;
  }
  values_[name] = value;
}

void ParamSet::assign(const std::string& assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throwUserError("--set expects name=value, got '" + assignment + "'");
  set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

const std::string& ParamSet::text(const std::string& name) const {
  find(name);
  return values_.at(name);
}
int ParamSet::getInt(const std::string& name) const { return std::stoi(text(name)); }
double ParamSet::getFloat(const std::string& name) const { return std::stod(text(name)); }
bool ParamSet::getBool(const std::string& name) const { return text(name) == "true"; }
const std::string& ParamSet::getChoice(const std::string& name) const { return text(name); }

nlohmann::json ParamSet::toJson() const {
  nlohmann::json j = nlohmann::json::object();
  for (const ParamDecl& d : decls_) {
    const std::string& v = values_.at(d.name);
    switch (d.type) {
      case ParamDecl::Type::Int: j[d.name] = std::stoll(v); break;
      case ParamDecl::Type::Float: j[d.name] = std::stod(v); break;
      case ParamDecl::Type::Bool: j[d.name] = v == "true"; break;
      case ParamDecl::Type::Choice: j[d.name] = v; break;
    }
  }
  return j;
}

}  // namespace ll
