// Statistical physics checks of the `event` backend (placeholder, filled below).
#include <gtest/gtest.h>
