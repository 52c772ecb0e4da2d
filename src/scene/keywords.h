// POV-Ray 3.7's reserved words: what the tokenizer treats as keywords, never as identifiers.
#pragma once

#include <string_view>

namespace mirage {

/// True when `word` is one of POV-Ray 3.7's reserved words (`sphere`, `rgb`, `x`, `pi`...).
/// Reserved words cannot be declared; an identifier that is neither reserved nor declared is
/// reported as an unknown keyword or an undefined identifier, depending on where it appears.
bool is_reserved_word(std::string_view word);

}  // namespace mirage
