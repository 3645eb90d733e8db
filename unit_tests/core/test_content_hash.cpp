// The content hash that decides whether a cached product is reused.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/core/ContentHash.hpp"

using cyclone::ContentHash;

TEST(ContentHash, FirstStreamIsFnv1a64) {
  // Test vectors of the FNV-1a 64-bit reference (Fowler, Noll, Vo): "" and "a".
  EXPECT_EQ(ContentHash().hex().substr(0, 16), "cbf29ce484222325");
  EXPECT_EQ(ContentHash().add("a", 1).hex().substr(0, 16), "af63dc4c8601ec8c");
}

TEST(ContentHash, SeparatesInputsThatConcatenateAlike) {
  EXPECT_NE(ContentHash().add(std::string("ab")).add(std::string("c")).hex(),
            ContentHash().add(std::string("a")).add(std::string("bc")).hex());
  EXPECT_EQ(ContentHash().add(1.5).add(3).hex(), ContentHash().add(1.5).add(3).hex());
  EXPECT_NE(ContentHash().add(1.5).hex(), ContentHash().add(std::nextafter(1.5, 2.0)).hex());
  EXPECT_NE(ContentHash().addAll(std::vector<int>{1, 2}).hex(), ContentHash().addAll(std::vector<int>{2, 1}).hex());
  EXPECT_EQ(ContentHash().hex().size(), 32u);
}
