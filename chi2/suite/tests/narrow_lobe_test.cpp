// A narrow lobe keeps its degrees of freedom on cells of equal probability. On a uniform
// grid, Phong of exponent 10⁶ and GGX of α 10⁻⁴ at 45° fall into a few cells, and an error
// inside the lobe that keeps those cells' mass is invisible at any sample count; cut by the
// claimed pdf, the same 64 × 32 cells keep well over a thousand dof (of 2,047), and both
// materials still pass. The sweep's equalcells_ cases assert that half (BsdfCase::minDof,
// checked by BsdfTest), so their equal-cells run happens once; here only the grid runs.
#include <gtest/gtest.h>

#include "chi2/suite/suite.h"

namespace verity::chi2::suite {

TEST(NarrowLobeCells, KeepTheirDegreesOfFreedomWhereTheGridTakesThem) {
  int tested = 0;
  for (const BsdfCase& c : bsdfCases()) {
    if (c.name.rfind("equalcells_", 0) != 0) continue;
    ++tested;
    EXPECT_EQ(c.cells, CellLayout::EqualProbability) << c.name;
    EXPECT_EQ(c.resolution, kSphereResolution) << c.name;
    EXPECT_GT(c.minDof, 1000) << c.name;
    BsdfCase grid = c;
    grid.cells = CellLayout::Grid;
    const TestResult onGrid = runBsdf(grid);
    EXPECT_LT(onGrid.chiSquare.dof, 200) << onGrid.report();
  }
  EXPECT_EQ(tested, 2);
}

}  // namespace verity::chi2::suite
