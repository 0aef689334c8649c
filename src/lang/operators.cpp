#include "lang/operators.hpp"

namespace aster::lang {

Operators& Operators::instance() {
  static Operators registry;
  return registry;
}

void Operators::add(const std::string& command, Operator op) { operators_[command] = std::move(op); }

const Operator* Operators::find(const std::string& command) const {
  auto it = operators_.find(command);
  return it == operators_.end() ? nullptr : &it->second;
}

void Operators::addMethod(const std::string& type, const std::string& method, Method m) {
  methods_[type][method] = std::move(m);
}

const Method* Operators::findMethod(const std::string& type, const std::string& method) const {
  auto t = methods_.find(type);
  if (t == methods_.end()) return nullptr;
  auto m = t->second.find(method);
  return m == t->second.end() ? nullptr : &m->second;
}

std::vector<std::string> Operators::methodNames(const std::string& type) const {
  std::vector<std::string> out;
  auto t = methods_.find(type);
  if (t != methods_.end())
    for (const auto& [name, m] : t->second) out.push_back(name);
  return out;
}

}  // namespace aster::lang
