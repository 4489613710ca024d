# Every fuzz target (tests/fuzz/fuzz_<name>.cpp): the fuzz build makes them, ctest runs each over
# its seeds and regressions and then fuzzes it briefly (label fuzz).
set(SHADELAB_FUZZ_TARGETS gltf obj off ply preset rubric cli preprocessor compile_log zip link)
