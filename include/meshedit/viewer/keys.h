#pragma once
/// \file
/// Keys and modifiers as the viewer's command layer sees them. The numeric values are
/// GLFW's key codes (printable keys are their US-layout ASCII codes), so the window code
/// converts with a cast; the command layer itself never includes GLFW.

#include <cstdint>

namespace meshedit::viewer {

enum class Key : int {
    Unknown = -1,
    Space = 32,
    Comma = 44,
    Minus = 45,  ///< '-'
    Period = 46,
    Slash = 47,  ///< '/' ('?' is Shift+Slash)
    Num0 = 48,   ///< '0' … '9' are Num0 + d
    Equal = 61,  ///< '=' ('+' is Shift+Equal)
    A = 65,      ///< 'A' … 'Z' are A + letter
    LeftBracket = 91,
    RightBracket = 93,
    Escape = 256,
    Enter = 257,
    Backspace = 259,
    Delete = 261,
    F1 = 290,
    KeypadDecimal = 330,
    KeypadSubtract = 333,
    KeypadAdd = 334,
    KeypadEnter = 335,
};

/// The key for a letter 'A'…'Z' or a digit '0'…'9'.
constexpr Key key_of(char c) {
    if (c >= 'a' && c <= 'z') {
        c = static_cast<char>(c - 'a' + 'A');
    }
    return static_cast<Key>(c);
}

/// Modifier bits (GLFW's values); Caps Lock and Num Lock are ignored by the bindings.
enum Mods : unsigned {
    kNoMods = 0,
    kShift = 0x1,
    kCtrl = 0x2,
    kAlt = 0x4,
};

}  // namespace meshedit::viewer
