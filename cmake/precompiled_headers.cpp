// Empty: the target owns the precompiled headers the module libraries share (CMakeLists.txt).
