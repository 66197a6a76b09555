#include "spec/schema_check.h"

#include <algorithm>
#include <iterator>
#include <set>

namespace crowdsim {
namespace {

/// The parameter type of this default alternative (an int default may stand for a number).
ParamType TypeOf(const ParamValue& v) {
  switch (v.index()) {
    case 0:
      return ParamType::kBool;
    case 1:
      return ParamType::kInt;
    case 2:
      return ParamType::kDouble;
    case 3:
      return ParamType::kString;
    default:
      return ParamType::kDoubleList;
  }
}

bool TypeFits(ParamType declared, ParamType given) {
  return declared == given || (declared == ParamType::kDouble && given == ParamType::kInt);
}

/// The enumerator and C++ type of its default as source spells them (2.0 prints as 2).
std::string Spelled(ParamType t) {
  switch (t) {
    case ParamType::kBool:
      return "ParamType::kBool takes a bool";
    case ParamType::kInt:
      return "ParamType::kInt takes a std::int64_t (an integer literal: 2, not 2.0)";
    case ParamType::kDouble:
      return "ParamType::kDouble takes a double";
    case ParamType::kString:
      return "ParamType::kString takes a std::string";
    case ParamType::kDoubleList:
      return "ParamType::kDoubleList takes a std::vector<double>";
  }
  return "";
}

/// The C++ type a default holds, in ParamValue's order of alternatives.
std::string CppTypeName(const ParamValue& v) {
  constexpr const char* kNames[] = {"bool", "std::int64_t", "double", "std::string",
                                    "std::vector<double>"};
  static_assert(std::variant_size_v<ParamValue> == std::size(kNames));
  return kNames[v.index()];
}

std::string Range(const ParamSpec& spec) {
  std::string range = "[";  // appended: "[" + a temporary string makes GCC 12 warn (-Wrestrict)
  range += FormatParamValue(spec.min) + ", " + FormatParamValue(spec.max) + "]";
  return range;
}

bool InRange(const ParamSpec& spec, double x) { return x >= spec.min && x <= spec.max; }

/// The problem of a default of the declared type, or "" when a suite could give it.
std::string DefaultProblem(const ParamSpec& spec) {
  const std::string head =
      "parameter '" + spec.name + "': default " + FormatParamValue(spec.default_value);
  if (const auto* list = std::get_if<std::vector<double>>(&spec.default_value)) {
    const auto out =
        std::find_if(list->begin(), list->end(), [&spec](double x) { return !InRange(spec, x); });
    if (out != list->end()) return head + " has an item outside its range " + Range(spec);
  } else if (const auto* s = std::get_if<std::string>(&spec.default_value)) {
    if (!spec.choices.empty() &&
        std::find(spec.choices.begin(), spec.choices.end(), *s) == spec.choices.end()) {
      std::string valid;
      for (const auto& c : spec.choices) valid += (valid.empty() ? "" : ", ") + c;
      return head + " is not one of its choices (" + valid + ")";
    }
  } else if (spec.type == ParamType::kInt || spec.type == ParamType::kDouble) {
    const auto* i = std::get_if<std::int64_t>(&spec.default_value);
    const double x = i ? static_cast<double>(*i) : std::get<double>(spec.default_value);
    if (!InRange(spec, x)) return head + " is outside its range " + Range(spec);
  }
  return "";
}

}  // namespace

std::vector<std::string> SchemaProblems(const ParamSchema& schema) {
  std::vector<std::string> problems;
  std::set<std::string> names;
  for (const ParamSpec& spec : schema) {
    if (spec.name.empty()) {
      problems.push_back("a parameter has an empty name");
      continue;
    }
    if (!names.insert(spec.name).second) {
      problems.push_back("parameter '" + spec.name + "' is declared twice");
      continue;
    }
    const ParamType given = TypeOf(spec.default_value);
    if (!TypeFits(spec.type, given)) {
      problems.push_back("parameter '" + spec.name + "': default " +
                         FormatParamValue(spec.default_value) + " is a " +
                         CppTypeName(spec.default_value) + ", but " + Spelled(spec.type));
      continue;
    }
    if (std::string problem = DefaultProblem(spec); !problem.empty()) {
      problems.push_back(std::move(problem));
    }
  }
  return problems;
}

}  // namespace crowdsim
