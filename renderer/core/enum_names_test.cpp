// Enum name tables: names in order, and each way between a name and its value.
#include "renderer/core/enum_names.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr EnumName<Fruit> kFruits[] = {{Fruit::Pear, "pear"}, {Fruit::Apple, "apple"}, {Fruit::Plum, "plum"}};

TEST(EnumNames, ListsTheNamesInTheTablesOrder) {
    EXPECT_EQ(enum_names(kFruits), (std::vector<std::string>{"pear", "apple", "plum"}));
}

TEST(EnumNames, MapsNamesToValuesAndBack) {
    EXPECT_EQ(enum_value(kFruits, "apple"), Fruit::Apple);
    EXPECT_EQ(enum_value(kFruits, "plum"), Fruit::Plum);
    EXPECT_STREQ(enum_name(kFruits, Fruit::Pear), "pear");
    EXPECT_THROW(enum_value(kFruits, "fig"), std::logic_error);
}

}  // namespace
}  // namespace isotrace
