#include "validation/studies/budget.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/error.h"

namespace verity::studies {

const char* budgetTypeName(BudgetType type) {
  return type == BudgetType::Spp ? "spp" : "time";
}

const char* budgetUnit(BudgetType type) {
  return type == BudgetType::Spp ? "spp" : "s";
}

BudgetType readBudgetType(const FieldReader& record) {
  const std::string name = record.text("budget_type");
  for (BudgetType type : {BudgetType::Spp, BudgetType::Time})
    if (name == budgetTypeName(type)) return type;
  record.fail("budget_type", "expected \"spp\" or \"time\", found \"" + name + "\"");
}

void checkBudgets(BudgetType type, const std::vector<double>& budgets) {
  const std::string option = type == BudgetType::Spp ? "--spp" : "--time";
  if (budgets.empty()) throw VerityError("", option, "no budget given");
  for (double b : budgets) {
    if (!(b > 0)) throw VerityError("", option, fmt::format("budgets must be positive, not {}", b));
    if (type == BudgetType::Spp && (b != std::floor(b) || b > std::numeric_limits<int>::max()))
      throw VerityError("", option,
                        fmt::format("samples per pixel must be a whole number, not {}", b));
  }
}

}  // namespace verity::studies
