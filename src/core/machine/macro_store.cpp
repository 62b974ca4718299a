// The custom macro B variables a run keeps (macro_store.h).
#include "machine/macro_store.h"

#include "klueng/core/machine/sink.h"

namespace klueng::core::machine::detail {

using gcode::MacroValue;

bool MacroStore::read(int n, int level, const MachineSink& clock, MacroValue& out) const {
  if (n >= 1 && n <= 33) {
    out = locals_[static_cast<std::size_t>(level)][static_cast<std::size_t>(n - 1)];
    return true;
  }
  if (n >= 100 && n <= 199) {
    out = common_[static_cast<std::size_t>(n - 100)];
    return true;
  }
  if (n >= 500 && n <= 999) {
    out = persistent_[static_cast<std::size_t>(n - 500)];
    return true;
  }
  switch (n) {
    case 3001:
      clockRead_ = true;
      out = MacroValue::of(clock.elapsed() * 1000.0 - timerBase_);
      return true;
    case 3002:
      clockRead_ = true;
      out = MacroValue::of(clock.elapsed() / 3600.0 - hourBase_);
      return true;
    case 3901: out = MacroValue::of(partsMachined_); return true;
    case 3902: out = MacroValue::of(partsRequired_); return true;
    case 4113: out = MacroValue::of(lastM_); return true;
    case 4114: out = MacroValue::of(lastN_); return true;
    case 4120: out = MacroValue::of(lastT_); return true;
    default: return false;
  }
}

std::uint64_t MacroStore::valueHash(std::uint64_t slot, const MacroValue& v) {
  if (v.vacant && bitsOf(v.value) == 0) return 0;
  return mixHash(mixHash(slot, bitsOf(v.value)), v.vacant);
}

bool MacroStore::write(int n, int level, const MachineSink& clock, MacroValue v) {
  if (n >= 1 && n <= 33) {
    setValue(locals_[static_cast<std::size_t>(level)][static_cast<std::size_t>(n - 1)], localSlot(level, n - 1), v);
  } else if (n >= 100 && n <= 199) {
    setValue(common_[static_cast<std::size_t>(n - 100)], globalSlot(n), v);
    noteWritten(n - 100);
  } else if (n >= 500 && n <= 999) {
    setValue(persistent_[static_cast<std::size_t>(n - 500)], globalSlot(n), v);
    noteWritten(n - 500 + 100);
  } else if (n == 3001) {
    timerBase_ = clock.elapsed() * 1000.0 - v.value;  // the timer reads v from now on
  } else if (n == 3002) {
    hourBase_ = clock.elapsed() / 3600.0 - v.value;
  } else if (n == 3901) {
    partsMachined_ = v.value;
  } else if (n == 3902) {
    partsRequired_ = v.value;
  } else {
    return false;
  }
  return true;
}

int MacroStore::pushLevel(const MacroLocals& arguments) {
  locals_.emplace_back();  // vacant: adds nothing to the hash
  const int level = static_cast<int>(locals_.size()) - 1;
  resetLocals(level, arguments);
  return level;
}

void MacroStore::resetLocals(int level, const MacroLocals& values) {
  MacroLocals& locals = locals_[static_cast<std::size_t>(level)];
  for (std::size_t i = 0; i < locals.size(); ++i) setValue(locals[i], localSlot(level, static_cast<int>(i)), values[i]);
}

void MacroStore::popLevel() {
  if (locals_.size() <= 1) return;
  resetLocals(static_cast<int>(locals_.size()) - 1, MacroLocals{});
  locals_.pop_back();
}

void MacroStore::loadPersistent(const std::map<int, double>& values) {
  for (const auto& [n, v] : values)
    if (n >= 500 && n <= 999)
      setValue(persistent_[static_cast<std::size_t>(n - 500)], globalSlot(n), MacroValue::of(v));
}

void MacroStore::savePersistent(std::map<int, double>& values) const {
  for (int n = 500; n <= 999; ++n) {
    const MacroValue& v = persistent_[static_cast<std::size_t>(n - 500)];
    if (v.vacant)
      values.erase(n);
    else
      values[n] = v.value;
  }
}

void MacroStore::writeState(RunStateWords& out) const {
  out.add(static_cast<int>(locals_.size()));
  for (const MacroLocals& level : locals_)
    for (const MacroValue& v : level) out.add(v);
  out.add(static_cast<int>(written_.size()));
  for (short slot : written_) {
    out.add(static_cast<int>(slot));
    out.add(slot < 100 ? common_[static_cast<std::size_t>(slot)] : persistent_[static_cast<std::size_t>(slot - 100)]);
  }
  // (The timers' bases are left out: they count only for a program that reads the timers.)
  out.add(partsMachined_);
  out.add(partsRequired_);
  out.add(lastT_);
  out.add(lastM_);
  out.add(lastN_);
}

void MacroStore::noteBlock(std::optional<int> t, std::optional<int> n, std::optional<int> m) {
  if (t) lastT_ = *t;
  if (n) lastN_ = *n;
  if (m) lastM_ = *m;
}

}  // namespace klueng::core::machine::detail
