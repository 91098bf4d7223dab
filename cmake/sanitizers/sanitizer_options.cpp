// Linked into every program of a SWSLAM_SANITIZE build (doc/sanitizers.md): the sanitizer
// runtimes read these default options at start-up, before ASAN_OPTIONS, UBSAN_OPTIONS,
// LSAN_OPTIONS and TSAN_OPTIONS, which still override them. Every report that the files
// beside this one do not suppress makes the program fail (ASan and UBSan: at once; TSan: exit
// status 66 after all reports), so a test cannot pass over it. The gtest discovery at build
// time runs with them too.
//
// SWSLAM_SANITIZER_DIR is this folder (set by CMake).

#define SWSLAM_SANITIZER_API extern "C" __attribute__((visibility("default"), used))

SWSLAM_SANITIZER_API const char* __asan_default_options()
{
  return "detect_leaks=1";
}

SWSLAM_SANITIZER_API const char* __lsan_default_options()
{
  return "suppressions=" SWSLAM_SANITIZER_DIR "/lsan.supp:print_suppressions=0";
}

SWSLAM_SANITIZER_API const char* __ubsan_default_options()
{
  return "halt_on_error=1:print_stacktrace=1:suppressions=" SWSLAM_SANITIZER_DIR "/ubsan.supp";
}

SWSLAM_SANITIZER_API const char* __tsan_default_options()
{
  // Every race is reported, then the exit status is 66.
  return "second_deadlock_stack=1:suppressions=" SWSLAM_SANITIZER_DIR "/tsan.supp";
}
