// A study's budget: samples per pixel or seconds of wall time.
#pragma once

#include <string>
#include <vector>

#include "validation/studies/record_fields.h"

namespace verity::studies {

enum class BudgetType { Spp, Time };

// "spp" or "time", as records and seeds spell it.
const char* budgetTypeName(BudgetType type);
// "spp" or "s", as file names and logs give a budget's unit.
const char* budgetUnit(BudgetType type);
// The record's "budget_type"; anything but "spp" or "time" is an error naming the file, the
// record and the key.
BudgetType readBudgetType(const FieldReader& record);

// Refuses no budgets, a budget that is not positive, and an spp budget that is not a whole
// number.
void checkBudgets(BudgetType type, const std::vector<double>& budgets);

}  // namespace verity::studies
