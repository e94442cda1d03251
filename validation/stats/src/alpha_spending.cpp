#include <verity/stats/alpha_spending.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace verity::validation {

SpendingFunction spendingFunction(const std::string& name) {
  if (name == "pocock") return SpendingFunction::Pocock;
  if (name == "obrien-fleming") return SpendingFunction::OBrienFleming;
  throw std::invalid_argument("spending function \"" + name +
                              "\" is neither pocock nor obrien-fleming");
}

std::string spendingName(SpendingFunction f) {
  return f == SpendingFunction::Pocock ? "pocock" : "obrien-fleming";
}

double spentLevel(SpendingFunction f, double alpha, double t) {
  if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("spentLevel: alpha not in (0, 1)");
  if (!(t >= 0 && t <= 1)) throw std::invalid_argument("spentLevel: t not in [0, 1]");
  if (t == 0) return 0;
  if (f == SpendingFunction::Pocock) return alpha * std::log(1 + (std::numbers::e - 1) * t);
  // Lan and DeMets (1983), O'Brien–Fleming-type: 2 − 2Φ(z_{1−α/2} / √t).
  const boost::math::normal normal;
  const double z = boost::math::quantile(boost::math::complement(normal, alpha / 2));
  return 2 * boost::math::cdf(boost::math::complement(normal, z / std::sqrt(t)));
}

double lookLevel(SpendingFunction f, double alpha, int look, int looks) {
  if (looks < 1 || look < 1 || look > looks)
    throw std::invalid_argument("lookLevel: look not in 1 ... looks");
  return spentLevel(f, alpha, double(look) / looks) -
         spentLevel(f, alpha, double(look - 1) / looks);
}

}  // namespace verity::validation
