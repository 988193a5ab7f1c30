#include "src/build_id.h"

#include <elf.h>
#include <fmt/format.h>
#include <link.h>

#include <cstring>

namespace colav {
namespace {

constexpr char kGnuNoteName[] = "GNU";  // the owner of NT_GNU_BUILD_ID notes

// Note entries are padded to 4 bytes.
constexpr ElfW(Word) NotePadded(ElfW(Word) size) { return (size + 3U) & ~ElfW(Word){3U}; }

// The build ID among the notes of [begin, end), or empty.
std::string BuildIdInNotes(const char* begin, const char* end) {
  for (const char* at = begin; at + sizeof(ElfW(Nhdr)) <= end;) {
    ElfW(Nhdr) header;
    std::memcpy(&header, at, sizeof(header));
    const char* name = at + sizeof(header);
    const char* description = name + NotePadded(header.n_namesz);
    if (header.n_type == NT_GNU_BUILD_ID && header.n_namesz == sizeof(kGnuNoteName) &&
        std::memcmp(name, kGnuNoteName, sizeof(kGnuNoteName)) == 0) {
      std::string hex;
      for (ElfW(Word) i = 0; i < header.n_descsz; ++i) {
        hex += fmt::format("{:02x}", static_cast<unsigned char>(description[i]));
      }
      return hex;
    }
    at = description + NotePadded(header.n_descsz);
  }
  return {};
}

// dl_iterate_phdr's callback: the first object listed is the executable itself.
int ReadExecutableBuildId(dl_phdr_info* info, std::size_t /*size*/, void* id) {
  for (ElfW(Half) i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    // The segment's address in memory is the object's load address plus its virtual address:
    // dl_iterate_phdr gives both as integers.
    // NOLINTNEXTLINE(performance-no-int-to-ptr)
    const char* notes = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
    *static_cast<std::string*>(id) = BuildIdInNotes(notes, notes + segment.p_memsz);
    if (!static_cast<std::string*>(id)->empty()) break;
  }
  return 1;  // stop after the executable
}

}  // namespace

std::string ProgramBuildId() {
  std::string id;
  dl_iterate_phdr(ReadExecutableBuildId, &id);
  return id;
}

}  // namespace colav
