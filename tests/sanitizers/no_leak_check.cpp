// Linked into the GL test executables of an ASan build only (cmake/OceanTargets.cmake, GL): LSan
// asks this at exit. Mesa's unloaded driver leaves allocations whose stacks no suppression can
// name; every other ASan and UBSan check of these processes stays on.
extern "C" int __lsan_is_turned_off() { return 1; }
