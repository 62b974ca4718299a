#include "klueng/core/io/file_write.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "io/text_util.h"
#include "klueng/core/diagnostic_codes.h"

#ifndef _WIN32
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>
#else
#include <fstream>
#endif

namespace klueng::core::io {

namespace {

namespace fs = std::filesystem;
using detail::makeDiagnostic;

Diagnostic writeError(const char* code, std::vector<std::string> args) {
  return makeDiagnostic(Severity::Error, code, 0, 0, 0, std::move(args));
}

// The system's reason in Thai for the errors a write commonly meets; others keep
// the system's own (English) words.
std::string thaiReason(int err) {
  switch (err) {
    case EACCES:
    case EPERM: return "ไม่มีสิทธิ์เขียน";
    case EROFS: return "ดิสก์เป็นแบบอ่านอย่างเดียว";
    case ENAMETOOLONG: return "ชื่อไฟล์ยาวเกินไป";
    case EIO: return "อุปกรณ์จัดเก็บข้อมูลขัดข้อง (I/O error)";
    case EBUSY:
    case ETXTBSY: return "ไฟล์กำลังถูกใช้งานอยู่";
    case EISDIR: return "เป็นโฟลเดอร์";
    default: return std::strerror(err);
  }
}

// The diagnostic for a failed write of `path` with errno `err`.
Diagnostic failure(const std::string& path, int err) {
  switch (err) {
    case ENOSPC:
    case EFBIG:  // the file size limit (ulimit -f) says "no space" as plainly as a full disk
#ifdef EDQUOT
    case EDQUOT:
#endif
      return writeError(codes::kNoSpaceToWrite, {path});
    default: return writeError(codes::kCannotWriteFile, {path, std::strerror(err), thaiReason(err)});
  }
}

std::string folderOf(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path().string() : std::string(".");
}

#ifndef _WIN32
// The temporary files being written, for the signal handler: fixed slots of
// lock-free atomics and plain buffers, all a handler may touch (async-signal-safe).
constexpr int kTempSlots = 32;
struct TempSlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled or emptied, 2 holds a path
  char path[4096]{};
};
TempSlot tempSlots[kTempSlots];
static_assert(std::atomic<int>::is_always_lock_free);

// Signals are blocked from mkstemp until the path is registered: none can fall in between.
class BlockedSignals {
 public:
  BlockedSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&set, sig);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockedSignals() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  BlockedSignals(const BlockedSignals&) = delete;
  BlockedSignals& operator=(const BlockedSignals&) = delete;

 private:
  sigset_t old_;
};

int registerTemp(const std::string& path) {
  if (path.size() >= sizeof(TempSlot::path)) return -1;
  for (int i = 0; i < kTempSlots; ++i) {
    int expected = 0;
    if (!tempSlots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(tempSlots[i].path, path.c_str(), path.size() + 1);
    tempSlots[i].state.store(2);
    return i;
  }
  return -1;  // more writes at once than slots: that one is not removed on a signal
}

void unregisterTemp(int slot) {
  if (slot < 0) return;
  tempSlots[slot].state.store(1);
  tempSlots[slot].path[0] = '\0';
  tempSlots[slot].state.store(0);
}

extern "C" void removeTempsAndReraise(int sig) {
  for (TempSlot& slot : tempSlots)
    if (slot.state.load() == 2) ::unlink(slot.path);
  ::signal(sig, SIG_DFL);  // then end as the signal would have
  ::raise(sig);
}

// Writes all of `bytes` to fd; 0, or the errno of the first failed write.
int writeAll(int fd, std::string_view bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    written += static_cast<std::size_t>(n);
  }
  return 0;
}
#endif

}  // namespace

void removeTemporaryFilesOnSignals() {
#ifndef _WIN32
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = removeTempsAndReraise;
    sigemptyset(&action.sa_mask);
    ::sigaction(sig, &action, nullptr);
  }
#endif
}

bool isReadOnlyFile(const std::string& path) {
#ifndef _WIN32
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  // Root may write anything: the permission bits are what the owner meant.
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) return true;
  return ::access(path.c_str(), W_OK) != 0 && errno == EACCES;
#else
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  return fs::is_regular_file(s) && (s.permissions() & fs::perms::owner_write) == fs::perms::none;
#endif
}

std::optional<Diagnostic> writeFileAtomic(const std::string& path, std::string_view bytes) {
  std::error_code ec;
  fs::path target(path);
  // A link is followed: the file it names gets the new bytes, the link stays a link.
  if (fs::is_symlink(fs::symlink_status(target, ec))) target = fs::weakly_canonical(target, ec);
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status)) return writeError(codes::kOutputIsFolder, {path});
  if (isReadOnlyFile(target.string())) return writeError(codes::kFileReadOnly, {path});
#ifndef _WIN32
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    // A device or a pipe cannot be replaced by renaming over it: write into it.
    // A pipe is opened without waiting (issue 42 item 4): with no reader at the
    // other end the open fails at once (ENXIO) and the output is refused, F157;
    // with one (`--json >(jq .)`, a FIFO someone reads) it is written as usual. A reader
    // started beside the run (`cat fifo & klueng-cli ...`) gets a second to open its end.
    int fd = ::open(target.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC | O_NONBLOCK);
    for (int wait = 0; fd < 0 && errno == ENXIO && fs::is_fifo(status) && wait < 20; ++wait) {
      ::usleep(50'000);
      fd = ::open(target.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC | O_NONBLOCK);
    }
    if (fd < 0 && errno == ENXIO && fs::is_fifo(status))
      return writeError(codes::kNotAnOrdinaryFile, {path, "a pipe (FIFO) that nobody reads", "ไปป์ (FIFO) ที่ไม่มีใครอ่าน"});
    if (fd < 0) return failure(path, errno);
    if (const int flags = ::fcntl(fd, F_GETFL); flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    int err = writeAll(fd, bytes);
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err != 0) return failure(path, err);
    return std::nullopt;
  }
  const std::string folder = folderOf(target);
  std::string temp = (fs::path(folder) / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  int fd = -1;
  int slot = -1;
  {
    const BlockedSignals blocked;
    fd = ::mkstemp(temp.data());
    if (fd >= 0) slot = registerTemp(temp);
  }
  // Unregistered once renamed or removed: a signal then has nothing of ours to remove.
  struct Unregister {
    int slot;
    ~Unregister() { unregisterTemp(slot); }
  } unregister{slot};
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT || err == ENOTDIR || err == EACCES || err == EPERM || err == EROFS)
      return writeError(codes::kFolderNotWritable, {path, folder});
    return failure(path, err);
  }
  // Keep the mode of the file we replace; new files get rw-r--r--.
  struct stat old {};
  ::fchmod(fd, ::stat(target.c_str(), &old) == 0 ? (old.st_mode & 07777) : 0644);
  // Every step is checked: a full disk may only show at fsync or close (NFS, delayed allocation).
  int err = writeAll(fd, bytes);
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(temp.c_str(), target.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(temp.c_str());
    return failure(path, err);
  }
  // Make the rename itself durable; failure here does not undo a complete write.
  if (const int dirFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY); dirFd >= 0) {
    ::fsync(dirFd);
    ::close(dirFd);
  }
  return std::nullopt;
#else
  const std::string temp = path + ".tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return writeError(codes::kFolderNotWritable, {path, folderOf(target)});
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      fs::remove(temp, ec);
      return writeError(codes::kCannotWriteFile, {path, "write failed", "เขียนไม่สำเร็จ"});
    }
  }
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    return writeError(codes::kCannotWriteFile, {path, ec.message(), ec.message()});
  }
  return std::nullopt;
#endif
}

std::optional<Diagnostic> outputOverwritesInput(const std::string& output, const std::vector<std::string>& inputs) {
  std::error_code ec;
  const fs::path out(output);
  const fs::file_status outStatus = fs::status(out, ec);
  // /dev/stdout and friends are streams, not files an input could be read from again.
  if (fs::exists(outStatus) && !fs::is_regular_file(outStatus)) return std::nullopt;
  const fs::path outCanonical = fs::weakly_canonical(fs::absolute(out, ec), ec);
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    std::error_code ec2;
    bool same = false;
    if (fs::exists(outStatus)) same = fs::equivalent(out, input, ec2);  // hard links, links, `..`
    if (!same) same = !ec && fs::weakly_canonical(fs::absolute(input, ec2), ec2) == outCanonical;
    if (same) return writeError(codes::kOutputIsInput, {output, input});
  }
  return std::nullopt;
}

}  // namespace klueng::core::io
