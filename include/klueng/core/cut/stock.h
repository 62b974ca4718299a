#pragma once
// The bar being turned, as per-Z-column radial material intervals (dexels).
// Work coordinates (SPEC 1): the stock occupies Z in [-length, 0] and radius
// in [bore/2, diameter/2] (bore 0 = a solid bar; a tube otherwise). Radial values are exact doubles; Z is resolved to
// `resolution` mm: column i stands for Z in [zLeft(i), zLeft(i) + resolution]
// and is sampled at its centre. Bores and undercuts are several intervals.
#include <algorithm>
#include <numbers>
#include <span>
#include <vector>

namespace klueng::core::cut {

constexpr double kDefaultResolution = 0.05;  // mm along Z

struct Interval {
  double lo = 0.0;  // radius, mm
  double hi = 0.0;
};

// What remove() takes while a tally is attached (Stock::setTally; cutting data, issue 39):
// the half section's area (z, radius) and, per column, the radial length removed.
struct RemovalTally {
  double sectionArea = 0.0;    // mm^2
  std::vector<double> radial;  // per column, mm (sized to the stock's columns on attach)
  std::vector<int> touched;    // the columns with radial > 0, in first-touch order
  void clear() {
    for (int i : touched) radial[static_cast<std::size_t>(i)] = 0.0;
    touched.clear();
    sectionArea = 0.0;
  }
};

class Stock {
 public:
  Stock() = default;
  // diameter, length > 0; resolution > 0 (coarsened so there are at most 2^21 columns);
  // bore in [0, diameter) (anything else is read as 0: a solid bar).
  Stock(double diameter, double length, double resolution = kDefaultResolution, double bore = 0.0);

  double diameter() const { return diameter_; }
  double bore() const { return bore_; }
  double length() const { return length_; }
  double resolution() const { return dz_; }
  int columnCount() const { return static_cast<int>(columns_.size()); }
  double columnWidth() const { return dz_; }
  double zLeft(int i) const { return -length_ + i * dz_; }
  double zRight(int i) const { return i + 1 == columnCount() ? 0.0 : -length_ + (i + 1) * dz_; }
  double zCentre(int i) const { return -length_ + (i + 0.5) * dz_; }
  // Column whose Z range holds z, or -1 outside the bar.
  int columnAt(double z) const;
  // Columns whose centres lie in [z0, z1] (z0 <= z1): [first, last], empty when first > last.
  void columnRange(double z0, double z1, int& first, int& last) const;

  // Material intervals of column i, ascending, disjoint.
  std::span<const Interval> column(int i) const;
  double outerRadius(int i) const { return outer_[i]; }  // 0 when the column is empty
  double innerRadius(int i) const;                       // start of the lowest interval (0 = solid)
  // Largest outer radius over columns [first, last] (fast: block maxima).
  double maxOuterRadius(int first, int last) const;
  // maxOuterRadius(first, last) > r, from the same columns and maxima, but stopping at the
  // first of them above r (true for a NaN r, as a comparison with the maximum would not skip).
  bool maxOuterAbove(int first, int last, double r) const;
  // Never below the outer radius of any column of aligned block b (columns
  // [b * kBlock, (b + 1) * kBlock)) or super-block s: what a sweep may skip.
  static constexpr int kBlock = 32;
  static constexpr int kSuper = kBlock * 32;
  double blockMaxOuter(int b) const { return blockMax_[static_cast<std::size_t>(b)]; }
  double superMaxOuter(int s) const { return superMax_[static_cast<std::size_t>(s)]; }

  // Removes radius range [lo, hi] from column i; returns the removed volume in mm^3.
  // (Inline: a sweep asks it of every column it passes, mostly above the material.)
  double remove(int i, double lo, double hi) {
    if (i < 0 || i >= columnCount() || !(hi > lo) || lo >= outer_[static_cast<std::size_t>(i)] || caught(i)) return 0.0;
    // The cut's commonest removal, here without a call: a batch turning a one-interval
    // column's outside down (what removeFromMaterial does in that case, to the bit).
    Interval* one =
        columns_[static_cast<std::size_t>(i)].size() == 1 ? columns_[static_cast<std::size_t>(i)].data() : nullptr;
    if (deferMaxima_ && !tally_ && one && hi >= one->hi && lo > one->lo) {
      const double area = one->hi * one->hi - lo * lo;
      one->hi = lo;
      lowerInBatch(i, lo);
      removed_ += std::numbers::pi * area * dz_;
      return std::numbers::pi * area * dz_;
    }
    return removeFromMaterial(i, lo, hi);
  }
  // Longest overlap, in mm, of radius range [lo, hi] with the material of column i (0 = none).
  double overlap(int i, double lo, double hi) const {
    if (i < 0 || i >= columnCount() || lo >= outer_[static_cast<std::size_t>(i)] || caught(i)) return 0.0;
    return overlapWithMaterial(i, lo, hi);
  }
  // A part cut off the bar falls into the parts catcher: its columns stay where they were, for the
  // finished part's profile and picture, but no later move cuts or touches them (issue 38: an
  // M99 repeat or the next part's facing sweeps through where the last part was).
  // Catches everything right of the first empty column from the chuck; true when it caught something.
  bool catchCutOffPart();
  bool caught(int i) const { return !caught_.empty() && caught_[static_cast<std::size_t>(i)] != 0; }

  // While a batch is open, remove() lowers a column's outer radius at once but leaves
  // its block and super-block maxima as they were (too high is allowed: they only
  // skip) until settle(): a pass that turns a run of columns down recomputes each
  // block once, not once per column (issue 29 item 14). Closing the batch settles.
  class Batch {
   public:
    explicit Batch(Stock& stock) : stock_(stock) { stock_.deferMaxima_ = true; }
    ~Batch() {
      stock_.settle();
      stock_.deferMaxima_ = false;
    }
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;

   private:
    Stock& stock_;
  };
  // The block and super-block maxima of the columns lowered since the last settle, exact again.
  void settle() {
    if (dirtyFirst_ <= dirtyLast_) settleDirty();
  }

  // Attach (or detach, nullptr) a tally every removal adds to; it must outlive the attachment.
  // A plain run has none: removeFromMaterial asks one pointer.
  void setTally(RemovalTally* tally);

  double volume() const;                             // mm^3 of material left
  double initialVolume() const;                      // mm^3 of the bar
  double removedVolume() const { return removed_; }  // sum of what remove() took

 private:
  void updateOuter(int i);
  // Column i's outer radius lowered to `now` inside a Batch: the maxima stay high (still
  // bounds) until settle().
  void lowerInBatch(int i, double now) {
    outer_[static_cast<std::size_t>(i)] = now;
    const int b = i / kBlock;
    dirtyFirst_ = dirtyFirst_ <= dirtyLast_ ? std::min(dirtyFirst_, b) : b;
    dirtyLast_ = std::max(dirtyLast_, b);
  }
  void settleDirty();
  double removeFromMaterial(int i, double lo, double hi);         // lo below the column's outer radius
  double overlapWithMaterial(int i, double lo, double hi) const;  // the same

  double diameter_ = 0.0;
  double bore_ = 0.0;
  double length_ = 0.0;
  double dz_ = kDefaultResolution;
  double removed_ = 0.0;
  // Most columns hold one interval; the rest spill into a per-column vector.
  std::vector<std::vector<Interval>> columns_;
  std::vector<double> outer_;
  std::vector<double> blockMax_;  // max outer radius per block of kBlock columns
  std::vector<double> superMax_;  // and per super-block of kSuper columns (kBlock blocks)
  std::vector<char> caught_;      // columns of parts cut off (empty until the first)
  RemovalTally* tally_ = nullptr;
  bool deferMaxima_ = false;  // a Batch is open
  int dirtyFirst_ = 0;        // blocks whose maxima wait for settle(): [first, last]
  int dirtyLast_ = -1;
};

// The chuck (SPEC 1 ext): jaws grip the stock's left `grip` mm; the body sits left of the bar.
struct Chuck {
  double stockLength = 0.0;         // mm
  double stockRadius = 0.0;         // mm
  double grip = 15.0;               // mm of bar inside the jaws
  double spindleBoreRadius = 20.0;  // the body's through-hole: nothing there to hit
  double jawHeight = 20.0;          // radial size of the jaws outside the bar
  double bodyWidth = 40.0;          // Z size of the chuck body left of the bar
  // Axis-aligned boxes in (z, x radius): the jaws, then the body (a ring
  // around the spindle bore).
  double jawZMin() const { return -stockLength; }
  double jawZMax() const { return -stockLength + grip; }
  double jawXMin() const { return stockRadius; }
  double jawXMax() const { return stockRadius + jawHeight; }
  double bodyZMin() const { return -stockLength - bodyWidth; }
  double bodyZMax() const { return -stockLength; }
  double bodyXMin() const { return spindleBoreRadius; }
  double bodyXMax() const { return stockRadius + jawHeight + 10.0; }
};

}  // namespace klueng::core::cut
