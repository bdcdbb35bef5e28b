// Looking an item up by one of its members (a name, a label) in what a function under test returned.
#pragma once

#include <vector>

namespace turf::test {

// The first of `items` whose `key` member equals `value`, or nullptr.
template <class Item, class Key, class Value>
const Item* FindBy(const std::vector<Item>& items, Key Item::*key, const Value& value) {
  for (const Item& item : items)
    if (item.*key == value) return &item;
  return nullptr;
}

}  // namespace turf::test
