// The target that compiles a set of the tests' precompiled headers (tests/CMakeLists.txt,
// ANISO_TEST_PCH); the tests of the set reuse them. It is not a test and is never run.
int main() { return 0; }
