#include "tasks/task_modules.h"

#include <cxxabi.h>
#include <dlfcn.h>
#include <elf.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>

#include "tasks/task_catalog.h"

#ifndef LIGHTLAB_STUDENT_MODULE_DIR
#define LIGHTLAB_STUDENT_MODULE_DIR ""
#endif
#ifndef LIGHTLAB_REFERENCE_MODULE_DIR
#define LIGHTLAB_REFERENCE_MODULE_DIR ""
#endif

namespace ll::tasks {

namespace {

namespace fs = std::filesystem;

std::string demangle(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> out(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), std::free);
  return status == 0 && out ? std::string(out.get()) : name;
}

// dlerror()'s "path: undefined symbol: _ZN..." as a sentence about the student's code.
std::string explainLoadError(const std::string& path, const std::string& error) {
  const std::string marker = "undefined symbol: ";
  const auto at = error.find(marker);
  if (at == std::string::npos) return path + " does not load: " + error;
  std::string symbol = error.substr(at + marker.size());
  while (!symbol.empty() && (symbol.back() == ' ' || symbol.back() == ')' || symbol.back() == '\n')) symbol.pop_back();
  const auto version = symbol.find(", version");
  if (version != std::string::npos) symbol = symbol.substr(0, version);
  const std::string name = demangle(symbol);
  if (name.rfind("ll::tasks::", 0) == 0 || name.find("takeTasksReported") != std::string::npos ||
      name.find("TaskLog") != std::string::npos)
    return path + " does not load: it uses " + name + ", which belongs to the framework and is not available to student code";
  return path + " does not load: it uses " + name +
         ", which is defined nowhere (a function declared but never written, or spelled differently from its declaration?)";
}

struct Module {
  void* handle = nullptr;
  std::string error;
};

std::mutex gMutex;
std::map<std::pair<int, bool>, Module> gModules;
std::atomic<uint64_t> gGeneration{0};

using EntryFn = void* (*)(const char*);
using IdFn = const char* (*)();

// Opens `path` (not cached): the handle, or the error. With `loadFrom`, the
// loader opens that file (a copy of `path`) instead; messages name `path`.
Module openModule(const std::string& path, int task, const std::string& loadFrom = "") {
  Module m;
  if (!fs::exists(path)) {
    m.error = path + ": no such task module (build it: cmake --build build)";
    return m;
  }
  dlerror();
  void* handle = dlopen((loadFrom.empty() ? path : loadFrom).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    m.error = explainLoadError(path, e ? e : "unknown error");
    return m;
  }
  const auto id = reinterpret_cast<IdFn>(dlsym(handle, "lightlab_task_id"));
  const auto entry = dlsym(handle, "lightlab_task_function");
  if (!id || !entry) {
    m.error = path + " is not a task module (no lightlab_task_function: build it with the project's CMake)";
    return m;
  }
  const std::string expected = taskCatalog()[static_cast<size_t>(task)].id;
  if (expected != id()) {
    m.error = path + " holds task " + std::string(id()) + ", not " + expected;
    return m;
  }
  m.handle = handle;
  return m;
}

std::string envOr(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : std::string(fallback);
}

// The defined, exported symbols of an ELF shared object's dynamic symbol table: name -> weak.
bool exportedSymbols(const std::string& path, std::map<std::string, bool>& out, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof(Elf64_Ehdr) || std::memcmp(bytes.data(), ELFMAG, SELFMAG) != 0 ||
      bytes[EI_CLASS] != ELFCLASS64) {
    error = path + " is not a 64-bit ELF shared object";
    return false;
  }
  Elf64_Ehdr eh;
  std::memcpy(&eh, bytes.data(), sizeof eh);
  const auto section = [&](size_t i) {
    Elf64_Shdr sh{};
    const size_t at = eh.e_shoff + i * eh.e_shentsize;
    if (at + sizeof sh <= bytes.size()) std::memcpy(&sh, bytes.data() + at, sizeof sh);
    return sh;
  };
  for (size_t i = 0; i < eh.e_shnum; ++i) {
    const Elf64_Shdr sh = section(i);
    if (sh.sh_type != SHT_DYNSYM) continue;
    const Elf64_Shdr strtab = section(sh.sh_link);
    for (size_t k = 0; k * sizeof(Elf64_Sym) < sh.sh_size; ++k) {
      Elf64_Sym sym{};
      const size_t at = sh.sh_offset + k * sizeof sym;
      if (at + sizeof sym > bytes.size()) break;
      std::memcpy(&sym, bytes.data() + at, sizeof sym);
      const int bind = ELF64_ST_BIND(sym.st_info), type = ELF64_ST_TYPE(sym.st_info);
      if (sym.st_shndx == SHN_UNDEF || (bind != STB_GLOBAL && bind != STB_WEAK && bind != STB_GNU_UNIQUE)) continue;
      if (ELF64_ST_VISIBILITY(sym.st_other) != STV_DEFAULT && ELF64_ST_VISIBILITY(sym.st_other) != STV_PROTECTED) continue;
      if (type != STT_FUNC && type != STT_OBJECT && type != STT_TLS && type != STT_GNU_IFUNC) continue;
      const size_t nameAt = strtab.sh_offset + sym.st_name;
      if (nameAt >= bytes.size()) continue;
      out[std::string(bytes.c_str() + nameAt)] = bind != STB_GLOBAL;
    }
  }
  return true;
}

}  // namespace

std::string studentModuleDir() { return envOr("LIGHTLAB_STUDENT_MODULES", LIGHTLAB_STUDENT_MODULE_DIR); }

std::string referenceModuleDir() { return envOr("LIGHTLAB_REFERENCE_MODULES", LIGHTLAB_REFERENCE_MODULE_DIR); }

std::string modulePath(const std::string& dir, int task) {
  return dir + "/lightlab_" + taskCatalog()[static_cast<size_t>(task)].id + ".so";
}

namespace {

// The folder of this process's reloaded module copies, removed at exit.
struct ReloadFolder {
  fs::path path;
  ReloadFolder() {
    std::error_code ec;
    path = fs::temp_directory_path(ec) / ("lightlab-reload-" + std::to_string(::getpid()));
  }
  ~ReloadFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// A student module after a reload: opened from a fresh copy, since the loader
// returns an already loaded module for the same path -- or for the same file
// identity (device, inode), which is why the copies stay on disk while the
// process runs: a deleted copy's inode number could come back for the next one.
Module openReloaded(const std::string& path, int task, uint64_t generation) {
  static ReloadFolder folder;
  std::error_code ec;
  fs::create_directories(folder.path, ec);
  const fs::path copy = folder.path / (std::to_string(generation) + "-" + fs::path(path).filename().string());
  if (!fs::exists(path) || !fs::copy_file(path, copy, fs::copy_options::overwrite_existing, ec))
    return openModule(path, task);  // names the missing file, or loads it in place
  return openModule(path, task, copy.string());
}

Module openStudentOrReference(int task, bool reference) {
  const std::string path = modulePath(reference ? referenceModuleDir() : studentModuleDir(), task);
  const uint64_t generation = gGeneration.load(std::memory_order_acquire);
  return reference || generation == 0 ? openModule(path, task) : openReloaded(path, task, generation);
}

}  // namespace

uint64_t studentModuleGeneration() { return gGeneration.load(std::memory_order_acquire); }

void reloadStudentModules() {
  std::lock_guard lock(gMutex);
  for (auto it = gModules.begin(); it != gModules.end();) {
    if (it->first.second) {
      ++it;
      continue;
    }
    // Not dlclose'd: text the old code handed to the framework (a stub's message, a
    // violation) may still be read; a retired module costs only its mapping.
    it = gModules.erase(it);
  }
  gGeneration.fetch_add(1, std::memory_order_acq_rel);
}

LoadedFunction loadTaskFunction(int task, const std::string& name, bool reference) {
  std::lock_guard lock(gMutex);
  auto [it, fresh] = gModules.try_emplace({task, reference});
  if (fresh) it->second = openStudentOrReference(task, reference);
  LoadedFunction f;
  if (!it->second.handle) {
    f.error = it->second.error;
    return f;
  }
  const auto entry = reinterpret_cast<EntryFn>(dlsym(it->second.handle, "lightlab_task_function"));
  f.address = entry(name.c_str());
  if (!f.address)
    f.error = modulePath(reference ? referenceModuleDir() : studentModuleDir(), task) + " has no function " + name;
  return f;
}

std::vector<std::string> checkModuleExports(const std::string& path, int task) {
  std::vector<std::string> problems;
  const TaskInfo& info = taskCatalog()[static_cast<size_t>(task)];
  std::map<std::string, bool> exported;
  std::string error;
  if (!exportedSymbols(path, exported, error)) return {error};
  for (const auto& [symbol, weak] : exported) {
    if (symbol == "lightlab_task_function" || symbol == "lightlab_task_id") continue;
    const std::string name = demangle(symbol);
    // Weak template instances of the standard library are harmless (and RTLD_LOCAL keeps them private).
    if (weak && name.rfind("ll::", 0) != 0) continue;
    problems.push_back(info.path() + " defines and exports " + name + ": a task module defines only " + info.id +
                       "'s functions (" + info.functions + "); it cannot replace framework or grader code");
  }
  return problems;
}

std::vector<std::string> checkModuleLoads(const std::string& path, int task) {
  std::vector<std::string> problems;
  const TaskInfo& info = taskCatalog()[static_cast<size_t>(task)];
  const Module m = openModule(path, task);
  if (!m.handle) {
    problems.push_back(m.error);
    return problems;
  }
  const auto entry = reinterpret_cast<EntryFn>(dlsym(m.handle, "lightlab_task_function"));
  for (const std::string& f : info.functionNames())
    if (!entry(f.c_str())) problems.push_back(path + " has no function " + f);
  return problems;
}

}  // namespace ll::tasks
