#include "elf_check.hpp"

#include <elf.h>
#include <link.h>  // ElfW: the host's ELF class

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

namespace relpos::plugins {
namespace {

using Ehdr = ElfW(Ehdr);
using Phdr = ElfW(Phdr);
using Shdr = ElfW(Shdr);

constexpr unsigned char kHostClass = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;
constexpr unsigned char kHostData =
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? ELFDATA2LSB : ELFDATA2MSB;
#if defined(__x86_64__)
constexpr int kHostMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kHostMachine = EM_AARCH64;
#elif defined(__i386__)
constexpr int kHostMachine = EM_386;
#elif defined(__arm__)
constexpr int kHostMachine = EM_ARM;
#elif defined(__powerpc64__)
constexpr int kHostMachine = EM_PPC64;
#elif defined(__riscv)
constexpr int kHostMachine = EM_RISCV;
#elif defined(__s390x__)
constexpr int kHostMachine = EM_S390;
#else
constexpr int kHostMachine = -1;  // a host this table does not know: dlopen decides
#endif

std::string machineName(int machine) {
  switch (machine) {
    case EM_X86_64:
      return "x86-64";
    case EM_AARCH64:
      return "AArch64";
    case EM_386:
      return "i386";
    case EM_ARM:
      return "ARM";
    case EM_PPC64:
      return "PowerPC64";
    case EM_RISCV:
      return "RISC-V";
    case EM_S390:
      return "S/390";
    default:
      return "e_machine " + std::to_string(machine);
  }
}

std::string segmentType(std::uint32_t type) {
  switch (type) {
    case PT_LOAD:
      return "LOAD";
    case PT_DYNAMIC:
      return "DYNAMIC";
    case PT_INTERP:
      return "INTERP";
    case PT_NOTE:
      return "NOTE";
    case PT_TLS:
      return "TLS";
    case PT_GNU_EH_FRAME:
      return "GNU_EH_FRAME";
    case PT_GNU_RELRO:
      return "GNU_RELRO";
    case PT_GNU_PROPERTY:
      return "GNU_PROPERTY";
    default:
      return "type " + std::to_string(type);
  }
}

// Whether [offset, offset + length) lies inside a file of `size` bytes (no overflow).
bool inside(std::uint64_t offset, std::uint64_t length, std::uint64_t size) {
  return offset <= size && length <= size - offset;
}

// offset + length, saturated: a header may hold any value.
std::uint64_t endOf(std::uint64_t offset, std::uint64_t length) {
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  return length > max - offset ? max : offset + length;
}

std::string endsPast(const std::string& what, std::uint64_t end, std::uint64_t size) {
  return "truncated: " + what + " ends at byte " + std::to_string(end) + " of a " +
         std::to_string(size) + "-byte file";
}

bool readAt(std::ifstream& in, std::uint64_t offset, void* out, std::size_t n) {
  in.seekg(static_cast<std::streamoff>(offset));
  return static_cast<bool>(in.read(static_cast<char*>(out), static_cast<std::streamsize>(n)));
}

std::string headerProblem(const Ehdr& h) {
  if (h.e_ident[EI_CLASS] != kHostClass)
    return std::string(h.e_ident[EI_CLASS] == ELFCLASS32 ? "a 32-bit" : "a 64-bit") +
           " ELF file; this relpos is " + (kHostClass == ELFCLASS64 ? "64-bit" : "32-bit");
  if (h.e_ident[EI_DATA] != kHostData)
    return std::string(h.e_ident[EI_DATA] == ELFDATA2MSB ? "a big-endian" : "a little-endian") +
           " ELF file; this host is " + (kHostData == ELFDATA2LSB ? "little-endian" : "big-endian");
  if (h.e_ident[EI_VERSION] != EV_CURRENT || h.e_version != EV_CURRENT)
    return "ELF version " + std::to_string(h.e_version) + ", not " + std::to_string(EV_CURRENT);
  if (kHostMachine >= 0 && h.e_machine != kHostMachine)
    return "built for another machine (" + machineName(h.e_machine) + "); this host is " +
           machineName(kHostMachine);
  if (h.e_type != ET_DYN) {
    switch (h.e_type) {
      case ET_EXEC:
        return "an executable, not a shared library";
      case ET_REL:
        return "an object file (.o), not a shared library";
      case ET_CORE:
        return "a core dump, not a shared library";
      default:
        return "ELF type " + std::to_string(h.e_type) + ", not a shared library";
    }
  }
  if (h.e_phnum == 0) return "no program headers";
  if (h.e_phentsize != sizeof(Phdr))
    return "program header entries of " + std::to_string(h.e_phentsize) + " bytes, expected " +
           std::to_string(sizeof(Phdr));
  if (h.e_shnum != 0 && h.e_shentsize != sizeof(Shdr))
    return "section header entries of " + std::to_string(h.e_shentsize) + " bytes, expected " +
           std::to_string(sizeof(Shdr));
  return "";
}

}  // namespace

std::string elfProblem(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "cannot be read";
  const std::streamoff end = in.tellg();
  if (end < 0) return "cannot be read";
  const auto size = static_cast<std::uint64_t>(end);
  if (size == 0) return "an empty file";

  Ehdr h{};
  const std::size_t got = static_cast<std::size_t>(std::min<std::uint64_t>(size, sizeof h));
  if (!readAt(in, 0, &h, got)) return "cannot be read";
  if (got < SELFMAG || std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0)
    return "not an ELF file: it does not start with 0x7f 'ELF'";
  if (got < sizeof h) return endsPast("the ELF header", sizeof h, size);
  if (std::string why = headerProblem(h); !why.empty()) return why;

  const std::uint64_t ph_bytes = std::uint64_t{h.e_phnum} * sizeof(Phdr);
  if (!inside(h.e_phoff, ph_bytes, size))
    return endsPast("the program header table", endOf(h.e_phoff, ph_bytes), size);

  std::vector<Phdr> segments(h.e_phnum);
  if (!readAt(in, h.e_phoff, segments.data(), ph_bytes)) return "cannot be read";
  bool loadable = false;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Phdr& p = segments[i];
    loadable |= p.p_type == PT_LOAD;
    // Every segment with file contents, not only LOAD and DYNAMIC: the dynamic loader also reads
    // NOTE and GNU_PROPERTY from the file.
    if (p.p_filesz != 0 && !inside(p.p_offset, p.p_filesz, size))
      return endsPast("segment " + std::to_string(i) + " (" + segmentType(p.p_type) + ")",
                      endOf(p.p_offset, p.p_filesz), size);
  }
  if (!loadable) return "no loadable segment";
  // dlopen does not read the section headers, but a table past the end is a cut file all the
  // same (it sits last).
  const std::uint64_t sh_bytes = std::uint64_t{h.e_shnum} * sizeof(Shdr);
  if (h.e_shoff != 0 && !inside(h.e_shoff, sh_bytes, size))
    return endsPast("the section header table", endOf(h.e_shoff, sh_bytes), size);
  return "";
}

}  // namespace relpos::plugins
