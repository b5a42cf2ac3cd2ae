// A valid shared library that is not a Collidoscope plugin: it exports a function, but not the
// entry point the host looks for.
extern "C" __attribute__((visibility("default"))) int collido_not_the_entry_point(void) {
  return 42;
}
