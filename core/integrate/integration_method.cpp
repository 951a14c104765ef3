#include "core/integrate/integration_method.hpp"

#include <stdexcept>

namespace orni {

IntegrationMethod IntegrationMethod::explicitRungeKutta(ErkMethod table) {
  IntegrationMethod m;
  m.table_ = table;
  return m;
}

IntegrationMethod IntegrationMethod::implicitExplicit(LinearImplicitPart linear_part,
                                                      ImexMethod pair) {
  if (!linear_part.apply || !linear_part.solve)
    throw std::invalid_argument("IntegrationMethod: the implicit part needs apply and solve");
  IntegrationMethod m;
  m.imex_ = true;
  m.pair_ = pair;
  m.linear_ = linear_part;
  return m;
}

const char* IntegrationMethod::name() const {
  if (!imex_) {
    switch (table_) {
      case ErkMethod::kDormandPrince5: return "ARKODE ERKStep Dormand-Prince 5(4)";
      case ErkMethod::kVerner6: return "ARKODE ERKStep Verner 6(5)";
      case ErkMethod::kFehlberg8: return "ARKODE ERKStep Fehlberg 8(7)";
      case ErkMethod::kBogackiShampine3: return "ARKODE ERKStep Bogacki-Shampine 3(2)";
      case ErkMethod::kArk436: return "ARKODE ERKStep ARK4(3)6L[2]SA explicit table";
    }
    return "ARKODE ERKStep";
  }
  switch (pair_) {
    case ImexMethod::kArk324: return "ARKODE ARKStep ARK3(2)4L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk436: return "ARKODE ARKStep ARK4(3)6L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk437: return "ARKODE ARKStep ARK4(3)7L[2]SA IMEX, modal stiffness implicit";
    case ImexMethod::kArk548: return "ARKODE ARKStep ARK5(4)8L[2]SAb IMEX, modal stiffness implicit";
  }
  return "ARKODE ARKStep IMEX";
}

}  // namespace orni
