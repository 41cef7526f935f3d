// A solver's parameters as a typed struct. Each member is bound to its ParamSpec in one table, so
// a solver reads members, never names: a spec cannot exist without its member, nor a member
// without its spec, and a misspelt name cannot compile.
//
//   struct PcisphParams { double eta = 0; int min_iterations = 0; ... };
//   ParamBinding<PcisphParams> b;
//   b.add({"eta", "1", 0.01, 1e-6, 0.5, "target average compression ..."}, &PcisphParams::eta);
//   info.params = b.specs();                  // the scene reader, `upf info`, docs/
//   PcisphParams p = b.bind(values);          // values filled and range-checked by the reader
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "framework/params/param_spec.h"

namespace upf {

template <class P>
class ParamBinding {
 public:
  ParamBinding& add(ParamSpec spec, double P::*member) { return push(std::move(spec), member); }
  // Whole numbers: the spec is marked integer, so the reader refuses 2.5.
  ParamBinding& add(ParamSpec spec, int P::*member) {
    spec.integer = true;
    return push(std::move(spec), member);
  }
  // Switches: 0 or 1 in the scene file.
  ParamBinding& add(ParamSpec spec, bool P::*member) {
    spec.integer = true;
    spec.min_value = 0;
    spec.max_value = 1;
    return push(std::move(spec), member);
  }

  std::vector<ParamSpec> specs() const {
    std::vector<ParamSpec> out;
    for (const auto& e : entries_) out.push_back(e.spec);
    return out;
  }

  // Every member from `values` (a ParamValues made from specs(), so every name is there).
  P bind(const ParamValues& values) const {
    P p{};
    for (const auto& e : entries_) {
      const double v = values.get(e.spec.name);
      std::visit(
          [&](auto member) {
            using T = std::remove_reference_t<decltype(p.*member)>;
            if constexpr (std::is_same_v<T, bool>) {
              p.*member = v != 0;
            } else {
              p.*member = T(v);
            }
          },
          e.member);
    }
    return p;
  }

 private:
  struct Entry {
    ParamSpec spec;
    std::variant<double P::*, int P::*, bool P::*> member;
  };
  template <class M>
  ParamBinding& push(ParamSpec spec, M member) {
    entries_.push_back({std::move(spec), member});
    return *this;
  }
  std::vector<Entry> entries_;
};

}  // namespace upf
