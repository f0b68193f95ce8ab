// The methods a run can choose between for one step of the program (how rays find their
// blockers, how form factors are computed, how the work is parallelised), each registered
// once under the name the command line, the result file and the docs use (docs/architecture.md,
// "How to add a method"). Every consumer looks a method up by name here; a name with no
// registration is a bug of the simulator (std::logic_error, exit 7), never a silent fallback
// to another method.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace ncube {

// `Method` has at least `std::string name` (the option's value and the result file's field)
// and `std::string doc` (what --help and docs/cli.md say of it).
template <class Method>
class MethodRegistry {
 public:
  // `kind`: what the methods are, for the error message ("visibility method"). The first
  // method is the default (the paper's).
  MethodRegistry(std::string kind, std::vector<Method> methods)
      : kind_(std::move(kind)), methods_(std::move(methods)) {
    if (methods_.empty()) throw std::logic_error("no " + kind_ + " registered");
    for (std::size_t i = 0; i < methods_.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (methods_[i].name == methods_[j].name)
          throw std::logic_error(kind_ + " \"" + methods_[i].name + "\" registered twice");
  }

  const std::vector<Method>& all() const { return methods_; }
  const Method& paper_default() const { return methods_.front(); }
  // The method registered as `name`; std::logic_error when there is none.
  const Method& at(const std::string& name) const {
    for (const Method& method : methods_)
      if (method.name == name) return method;
    throw std::logic_error("no " + kind_ + " registered as \"" + name + "\"");
  }
  bool contains(const std::string& name) const {
    for (const Method& method : methods_)
      if (method.name == name) return true;
    return false;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> names;
    for (const Method& method : methods_) names.push_back(method.name);
    return names;
  }
  // "a (doc of a), b (doc of b) or c (doc of c)": the choices as --help lists them.
  std::string described() const {
    std::string text;
    for (std::size_t i = 0; i < methods_.size(); ++i) {
      if (i > 0) text += i + 1 == methods_.size() ? " or " : ", ";
      text += methods_[i].name + " (" + methods_[i].doc + ")";
    }
    return text;
  }

 private:
  std::string kind_;
  std::vector<Method> methods_;
};

}  // namespace ncube
