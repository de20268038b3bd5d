// The libFuzzer target of one reader, chosen at build time (SANSUI_FUZZ_READER, see
// fuzz_targets.cmake): any input must end in a result or an InputError. Built by
// `scripts/build --sanitize` with clang; `scripts/fuzz NAME MINUTES` runs one for long.
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <linux/filter.h>
#include <linux/seccomp.h>

#include "core/memory.hpp"
#include "tests/fuzz/fuzz_readers.hpp"

namespace {

/// The VRT reader must never reach the network: a socket other than a local one raises SIGSYS
/// (seccomp), which aborts, so that libFuzzer keeps the input as a crash.
void forbid_network() {
  std::signal(SIGSYS, [](int) { std::abort(); });
  sock_filter filter[] = {
      BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_socket, 0, 3),
      BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, args[0])),
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AF_UNIX, 1, 0),
      BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_TRAP),
      BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
  };
  sock_fprog program{static_cast<unsigned short>(sizeof filter / sizeof filter[0]), filter};
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) != 0) std::abort();
}

const std::filesystem::path& scratch() {
  static const std::filesystem::path folder = [] {
    auto path = std::filesystem::temp_directory_path() / ("sansui-fuzz-" SANSUI_FUZZ_READER "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Inputs may declare huge sizes: the readers must refuse those above the limit before they
  // allocate, and libFuzzer's own limit (-rss_limit_mb) must never be what stops them.
  sansui::set_memory_limit_bytes(std::size_t{512} << 20);
  if (std::string_view(SANSUI_FUZZ_READER) == "gdal_vrt") forbid_network();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sansui::test::FuzzReader& reader = sansui::test::fuzz_reader(SANSUI_FUZZ_READER);
  (void)sansui::test::read_fuzz_input(reader, std::string_view(reinterpret_cast<const char*>(data), size), scratch());
  return 0;
}
