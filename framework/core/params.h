// Parameters declared once by a technique or accelerator (name, type, range,
// default, help). The command line (--set name=value), the GUI widgets,
// presets and grading specs are all generated from these declarations.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace ll {

struct ParamDecl {
  enum class Type { Int, Float, Bool, Choice };
  std::string name;
  Type type = Type::Float;
  std::string defaultValue;          // as it would be written on the command line
  double min = 0.0, max = 0.0;       // inclusive range for Int and Float
  std::vector<std::string> choices;  // allowed values for Choice
  std::string help;

  static ParamDecl integer(std::string name, int def, int min, int max, std::string help);
  static ParamDecl real(std::string name, double def, double min, double max, std::string help);
  static ParamDecl boolean(std::string name, bool def, std::string help);
  static ParamDecl choice(std::string name, std::string def, std::vector<std::string> choices,
                          std::string help);

  std::string typeName() const;  // "int", "float", "bool", "choice"
  std::string rangeText() const;  // "[1, 256]", "one of: a, b", "true or false"
};

// Values for a list of declarations; starts at the defaults.
class ParamSet {
 public:
  ParamSet() = default;
  // owner names the technique/accelerator in messages, e.g. "technique 'raycast'".
  ParamSet(std::string owner, std::vector<ParamDecl> decls);

  // Validates and stores; throws UserError naming the parameter and its range.
  void set(const std::string& name, const std::string& value);
  // Applies "name=value"; throws UserError on a malformed assignment.
  void assign(const std::string& assignment);
  bool has(const std::string& name) const;

  int getInt(const std::string& name) const;
  double getFloat(const std::string& name) const;
  bool getBool(const std::string& name) const;
  const std::string& getChoice(const std::string& name) const;
  const std::string& text(const std::string& name) const;  // the value as written

  const std::vector<ParamDecl>& decls() const { return decls_; }
  const std::string& owner() const { return owner_; }
  nlohmann::json toJson() const;

 private:
  const ParamDecl& find(const std::string& name) const;
  std::string owner_;
  std::vector<ParamDecl> decls_;
  std::map<std::string, std::string> values_;
};

}  // namespace ll
