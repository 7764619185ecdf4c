// Keeps the geometry test executable buildable while its suites are written.
#include <gtest/gtest.h>
