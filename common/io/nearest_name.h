// nearestName: the likely intended spelling of a misspelled option, key or command.
#pragma once

#include <string>
#include <vector>

namespace giocal {

/// Edit (Levenshtein) distance between two strings.
size_t editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word` in edit distance if within `max_distance` edits, else empty.
std::string nearestName(const std::string& word, const std::vector<std::string>& candidates,
                        size_t max_distance);

}  // namespace giocal
