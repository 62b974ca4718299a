#pragma once
// Grading against a reference part (issue 11, class grading): where the
// student's finished part differs from the reference's, on the diameter. A
// column of the student's part may lie anywhere between the reference's
// smallest and largest radius within `zTolerance` of it, so a shoulder a few
// hundredths of a millimetre off in Z is not read as a whole step of error.
#include "klueng/core/cut/stock.h"

namespace klueng::core::cut {

struct PartDeviation {
  double leftover = 0.0;   // mm on the diameter: material left outside the reference part (largest)
  double leftoverZ = 0.0;  // where
  double gouge = 0.0;      // mm on the diameter: material cut away inside the reference part (largest)
  double gougeZ = 0.0;
  bool sameBar = true;  // both parts come from the same bar (diameter, length, bore)
};

PartDeviation compareParts(const Stock& student, const Stock& reference, double zTolerance = 0.05);

}  // namespace klueng::core::cut
