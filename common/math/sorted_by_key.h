// Vectors of (key, value) pairs kept sorted by key: the per-epoch tables of the GNSS checks,
// rebuilt every epoch, where a std::map cost an allocation per entry.
#pragma once

#include <algorithm>

namespace giocal {

/// Orders (key, value) pairs by their keys.
struct ByKey {
  template <class A, class B>
  bool operator()(const A& a, const B& b) const {
    return a.first < b.first;
  }
};

/// The first entry of a vector of pairs sorted by key whose key is not before `key`: where an
/// entry of `key` is or would be inserted.
template <class V, class K>
auto lowerBoundKey(V& v, const K& key) {
  return std::lower_bound(v.begin(), v.end(), key,
                          [](const auto& e, const K& k) { return e.first < k; });
}

/// The entry of `key` in a vector of pairs sorted by key, or end().
template <class V, class K>
auto findKey(V& v, const K& key) {
  const auto it = lowerBoundKey(v, key);
  return it != v.end() && it->first == key ? it : v.end();
}

}  // namespace giocal
