// Edit distance between names, for "did you mean" in every message that refuses a misspelt
// name (a Mirage_ setting, a command-line option, a subcommand).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace mirage {

/// Levenshtein distance: the fewest insertions, deletions and substitutions of one byte that
/// turn `a` into `b`.
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The name of `names` nearest to `word`, fewer than `below` edits away (the first of equals);
/// empty when none is.
std::string closest_name(const std::string& word, const std::vector<std::string>& names,
                         std::size_t below);

}  // namespace mirage
