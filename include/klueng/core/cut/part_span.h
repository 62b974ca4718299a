#pragma once
// The finished part's span inside the cut stock (issue 28 item 3): what a drawing
// shows. A parting cut (columns left empty, or a pip of at most kPipRadius)
// separates the part, the piece on the Z0 side, from the bar left in the
// chuck; without one, the bar's untouched left end (the chucked stub, still
// at the bar's own sizes) is not part of the part.
#include "klueng/core/cut/part_features.h"
#include "klueng/core/cut/stock.h"

namespace klueng::core::cut {

// A column whose material reaches no further than this from the axis is a parting gap.
inline constexpr double kPipRadius = 1.0;  // mm
// The largest tool nose whose fillet is left out at an unparted part's end.
inline constexpr double kNoseFillet = 1.6;  // mm

struct PartSpan {
  double zLeft = 0.0;  // the part's ends (column edges); zLeft < zRight when the stock holds material
  double zRight = 0.0;
  bool parted = false;       // a parting gap lies left of the part
  bool stubLeftOut = false;  // untouched bar left of the part was left out
  // The nose's fillet in the corner with the bar left on is not the part's:
  // from zLeft to trimUntil nothing stands above trimRadius (the last step's).
  double trimRadius = 0.0;
  double trimUntil = -1e300;
  bool empty() const { return !(zLeft < zRight); }
  double length() const { return zRight - zLeft; }
};

// Where the finished part lies in `stock`; the whole stock when nothing was cut.
PartSpan finishedPartSpan(const Stock& stock);
// The stock with everything outside `span` removed (same columns, same Z).
Stock cropToSpan(const Stock& stock, const PartSpan& span);

// The chamfer before an outside thread, which the thread's grooves cut through
// (its crests still lie on the chamfer's line): added to part.outside before
// the thread, measured from those crests. A drawing gives it as the designer did.
void addThreadLeadChamfers(const Stock& stock, PartFeatures& part);

}  // namespace klueng::core::cut
