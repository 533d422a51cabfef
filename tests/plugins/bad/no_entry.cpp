// A shared library that is not a relpos plugin: it exports a function, but no RELPOS_PLUGIN.
extern "C" __attribute__((visibility("default"))) int relpos_something_else() { return 42; }
