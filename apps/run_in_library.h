#pragma once
// Runs a heavy program's work in its library, lib<program>-run.so (programs.h), loaded only now
// that the command line is parsed. The executable finds it by its RUNPATH: the build's lib/
// folder, or lib/swslam/ of the installation.

#include <dlfcn.h>

#include <iostream>
#include <string>
#include <type_traits>

namespace swslam::cli
{
/** Loads `program`'s library and calls its entry point `entry` (of type Entry) with `options`;
 * returns the program's exit code, or 1 after a message naming the library and dlerror()'s
 * reason if the library or its entry point cannot be loaded. */
template <class Entry, class Options>
int runInLibrary(const char* program, const char* entry, const Options& options)
{
  static_assert(std::is_same_v<Entry, int(const Options*)>, "the entry point takes these options");
  const std::string library = "lib" + std::string(program) + "-run.so";
  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
  {
    std::cerr << program << ": cannot load " << library << ": " << dlerror() << "\n";
    return 1;
  }
  auto* run = reinterpret_cast<Entry*>(dlsym(handle, entry));
  if (!run)
  {
    std::cerr << program << ": " << library << " has no " << entry << ": " << dlerror() << "\n";
    return 1;
  }
  return run(&options);  // the library stays loaded: its static objects live until exit
}
}  // namespace swslam::cli

/** Runs `program`'s entry point, a function declared in programs.h, with `options`: its name
 * and type are the declaration's, which the executable never links. */
#define SWSLAM_RUN_IN_LIBRARY(program, entry, options) \
  swslam::cli::runInLibrary<decltype(entry)>(program, #entry, options)
