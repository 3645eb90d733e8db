// Linked into every test program of a CYCLONE_SANITIZE build: LeakSanitizer off by
// default, since OpenMPI and Trilinos keep allocations until exit that are not
// Cyclone's (thousands of reports from libtrilinos_loca and libmpi alone); address
// errors and undefined behaviour are still fatal. ASAN_OPTIONS overrides it.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
