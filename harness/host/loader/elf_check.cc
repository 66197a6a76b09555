#include "loader/elf_check.h"

#include <elf.h>

#include <cstring>
#include <fstream>
#include <vector>

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

std::string CutShort(const std::string& what, std::uint64_t end, std::uintmax_t size) {
  return "is cut short: " + what + " ends at byte " + std::to_string(end) + " but the file has " +
         std::to_string(size) + " bytes (an interrupted copy or build?); copy or build it again";
}

}  // namespace

std::string ElfFileProblem(const fs::path& file) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) return "cannot be read (" + ec.message() + ")";
  std::ifstream in(file, std::ios::binary);
  Elf64_Ehdr eh{};
  if (!in.read(reinterpret_cast<char*>(&eh), sizeof(eh))) {
    return size >= SELFMAG && std::memcmp(&eh, ELFMAG, SELFMAG) == 0
               ? CutShort("the ELF header", sizeof(eh), size)
               : "is not a shared library (no ELF header)";
  }
  if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0)
    return "is not a shared library (no ELF header)";
  if (eh.e_ident[EI_CLASS] != ELFCLASS64 ||
      (eh.e_machine != EM_X86_64 && eh.e_machine != EM_AARCH64))
    return "is an ELF file for another kind of machine";
  if (eh.e_type != ET_DYN) return "is an ELF file but not a shared library";
  const std::uint64_t ph_end = eh.e_phoff + std::uint64_t{eh.e_phnum} * eh.e_phentsize;
  if (ph_end > size) return CutShort("its program header table", ph_end, size);
  const std::uint64_t sh_end = eh.e_shoff + std::uint64_t{eh.e_shnum} * eh.e_shentsize;
  if (sh_end > size) return CutShort("its section header table", sh_end, size);
  if (eh.e_phentsize != sizeof(Elf64_Phdr)) return "has program headers of an unknown size";
  std::vector<Elf64_Phdr> ph(eh.e_phnum);
  in.seekg(static_cast<std::streamoff>(eh.e_phoff));
  if (!in.read(reinterpret_cast<char*>(ph.data()),
               static_cast<std::streamsize>(ph.size() * sizeof(Elf64_Phdr)))) {
    return CutShort("its program header table", ph_end, size);
  }
  for (const Elf64_Phdr& p : ph) {
    if (p.p_type == PT_LOAD && p.p_offset + p.p_filesz > size)
      return CutShort("a loaded segment", p.p_offset + p.p_filesz, size);
  }
  return "";
}

}  // namespace crowdsim
