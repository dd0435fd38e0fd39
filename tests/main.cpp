// Catch2 2.13 entry point: all test files under tests/ link into one binary.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
