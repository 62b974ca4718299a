// The registry of machines (SPEC 13, issue 27): every profile comes from a
// machine file. The shipped files are built into the program
// (shipped_machines.cpp is generated from resources/machines/*.machine) and
// read on first use; user files are added with registerMachine.
#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>

#include "code_index.h"
#include "klueng/core/gcode/machine_file.h"

namespace klueng::core::gcode {

namespace {

struct Entry {
  MachineDefinition def;
  detail::CodeIndex codes;
};

constexpr std::size_t kMaxMachines = 200;

struct Registry {
  // Entries are never freed: a replaced machine's profile may still be read by a
  // worker thread that copied the reference (a check in flight).
  std::array<std::atomic<const Entry*>, kMaxMachines> slots{};
  std::atomic<int> count{0};
  std::mutex writing;
};

Registry& registryNoInit() {
  static Registry r;
  return r;
}

// Fixes the profile's views onto the entry's own strings.
void bind(Entry& e) {
  MachineProfile& p = e.def.profile;
  p.id = e.def.id;
  p.nameEn = e.def.nameEn;
  p.nameTh = e.def.nameTh;
  p.letters = e.def.letters;
  p.file = e.def.file;
  p.text = e.def.text;
  p.oneShotsWithMotion = e.def.oneShots;
  p.mCodes = e.def.mCodes;
  p.errorsAsWarnings = e.def.errorsAsWarnings;
}

Dialect add(Registry& r, MachineDefinition def) {
  auto* entry = new Entry{std::move(def), {}};
  bind(*entry);
  const std::lock_guard lock(r.writing);
  const int n = r.count.load();
  int slot = n;
  for (int i = 0; i < n; ++i)
    if (r.slots[static_cast<std::size_t>(i)].load()->def.id == entry->def.id) slot = i;
  if (slot >= static_cast<int>(kMaxMachines)) slot = n - 1;  // full: the last place is reused
  entry->def.profile.dialect = static_cast<Dialect>(slot);
  detail::buildCodeIndex(entry->def.profile, entry->codes);
  r.slots[static_cast<std::size_t>(slot)].store(entry);
  if (slot == n) r.count.store(n + 1);
  return entry->def.profile.dialect;
}

thread_local bool loadingShipped = false;

Registry& registry() {
  static const bool shipped = [] {
    Registry& r = registryNoInit();
    loadingShipped = true;
    // Families first (Dialect::Fanuc, Haas, Classic are their places); a `base =`
    // names a machine read before it.
    for (const ShippedMachineFile& f : shippedMachineFiles()) {
      MachineFileRead read = parseMachineFile(f.text, std::string(f.name));
      if (!read.machine) continue;  // tests/core/gcode/machine_file_test.cpp reads each one clean
      read.machine->file.clear();
      add(r, std::move(*read.machine));
    }
    loadingShipped = false;
    return true;
  }();
  (void)shipped;
  return registryNoInit();
}

const Entry& entryOf(Dialect dialect) {
  Registry& r = registry();
  const auto i = static_cast<std::size_t>(dialect);
  const Entry* e = i < static_cast<std::size_t>(r.count.load()) ? r.slots[i].load() : nullptr;
  return e ? *e : *r.slots[0].load();
}

}  // namespace

Dialect registerMachine(MachineDefinition machine) { return add(registry(), std::move(machine)); }

const MachineProfile& machineProfile(Dialect dialect) { return entryOf(dialect).def.profile; }

int machineCount() { return registry().count.load(); }

std::vector<const MachineProfile*> machineProfiles() {
  Registry& r = registry();
  std::vector<const MachineProfile*> out;
  const int n = r.count.load();
  for (int i = 0; i < n; ++i) out.push_back(&r.slots[static_cast<std::size_t>(i)].load()->def.profile);
  return out;
}

bool parseDialectId(std::string_view id, Dialect& out) {
  for (const MachineProfile* p : machineProfiles())
    if (p->id == id) {
      out = p->dialect;
      return true;
    }
  return false;
}

namespace detail {
const CodeIndex& codeIndexOf(Dialect dialect) { return entryOf(dialect).codes; }

const MachineProfile* loadedMachine(std::string_view id) {
  // While the shipped files are read, a `base =` finds the ones read before it.
  Registry& r = loadingShipped ? registryNoInit() : registry();
  const int n = r.count.load();
  for (int i = 0; i < n; ++i)
    if (const Entry* e = r.slots[static_cast<std::size_t>(i)].load(); e->def.id == id) return &e->def.profile;
  return nullptr;
}

std::string loadedMachineIds() {
  Registry& r = loadingShipped ? registryNoInit() : registry();
  std::string ids;
  const int n = r.count.load();
  for (int i = 0; i < n; ++i) ids += (ids.empty() ? "" : ", ") + r.slots[static_cast<std::size_t>(i)].load()->def.id;
  return ids;
}
}  // namespace detail

}  // namespace klueng::core::gcode
