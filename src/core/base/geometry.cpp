#include "klueng/core/geometry.h"

namespace klueng::core {

Vec2 tipVector(int tip) {
  //  2 6 1
  //  7 0 5      (+X up, +Z right); vector is (dz, dx)
  //  3 8 4
  switch (tip) {
    case 1: return Vec2(1, 1);
    case 2: return Vec2(-1, 1);
    case 3: return Vec2(-1, -1);
    case 4: return Vec2(1, -1);
    case 5: return Vec2(1, 0);
    case 6: return Vec2(0, 1);
    case 7: return Vec2(-1, 0);
    case 8: return Vec2(0, -1);
    default: return Vec2(0, 0);
  }
}

}  // namespace klueng::core
