// Argument parsing, number parsing and input loading shared by the subcommands.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "cli.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {
namespace {

const OptionSpec* find_option(const std::vector<OptionSpec>& options, const std::string& name) {
    for (const OptionSpec& o : options) {
        if (o.name == name) {
            return &o;
        }
    }
    return nullptr;
}

}  // namespace

Args parse_args(const std::string& command, const std::vector<std::string>& argv,
                const std::vector<OptionSpec>& options) {
    Args args;
    bool options_done = false;
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& word = argv[i];
        // A lone "-" or a negative number is a positional, not an option.
        const bool looks_like_option = !options_done && word.size() > 1 && word[0] == '-' &&
                                       !std::isdigit(static_cast<unsigned char>(word[1]));
        if (!looks_like_option) {
            args.positional.push_back(word);
            continue;
        }
        if (word == "--") {
            options_done = true;
            continue;
        }
        if (word == "-h" || word == "--help") {
            args.help = true;
            continue;
        }
        // Short options may carry their value attached, as in "-n2".
        if (word[1] != '-' && word.size() > 2) {
            const OptionSpec* shortopt = find_option(options, word.substr(0, 2));
            if (shortopt != nullptr && shortopt->takes_value) {
                args.values[shortopt->name] = word.substr(2);
                continue;
            }
        }
        const auto eq = word.find('=');
        const std::string name = word.substr(0, eq);
        const OptionSpec* spec = find_option(options, name);
        if (spec == nullptr) {
            throw UsageError(command + ": unknown option '" + name + "' (see meshedit " + command +
                             " --help)");
        }
        if (!spec->takes_value) {
            if (eq != std::string::npos) {
                throw UsageError(command + ": option '" + name + "' takes no value");
            }
            args.flags.insert(spec->name);
            continue;
        }
        std::string value;
        if (eq != std::string::npos) {
            value = word.substr(eq + 1);
        } else if (i + 1 < argv.size()) {
            value = argv[++i];
        } else {
            throw UsageError(command + ": option '" + name + "' needs a value");
        }
        args.values[spec->name] = value;
    }
    return args;
}

void expect_positionals(const std::string& command, const Args& args, std::size_t count,
                        const std::string& what) {
    if (args.positional.size() < count) {
        throw UsageError(command + ": missing " + what + " (see meshedit " + command + " --help)");
    }
    if (args.positional.size() > count) {
        throw UsageError(command + ": unexpected argument '" + args.positional[count] +
                         "' (see meshedit " + command + " --help)");
    }
}

double parse_double(const std::string& text, const std::string& option) {
    double x = 0.0;
    const char* first = text.data();
    const char* last = first + text.size();
    // from_chars rejects a leading '+', which people do type.
    if (first != last && *first == '+') {
        ++first;
    }
    const auto [end, ec] = std::from_chars(first, last, x);
    if (text.empty() || ec != std::errc() || end != last || !std::isfinite(x)) {
        throw UsageError("bad number '" + text + "' for " + option);
    }
    return x;
}

int parse_int(const std::string& text, const std::string& option, int min, int max) {
    int x = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
        throw UsageError("bad number '" + text + "' for " + option);
    }
    if (x < min || x > max) {
        throw UsageError("bad number '" + text + "' for " + option + " (expected " +
                         std::to_string(min) + " to " + std::to_string(max) + ")");
    }
    return x;
}

std::string format_number(double x) {
    if (x == 0.0) {
        return "0";  // also for -0, which would only confuse readers
    }
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return ec == std::errc() ? std::string(buffer, end) : std::to_string(x);
}

void print_notice(const std::string& text) {
    std::fprintf(stderr, "meshedit: note: %s\n", text.c_str());
}

LoadedDocument load_surface(const std::filesystem::path& path, int density) {
    if (file_extension(path) == ".bzc") {
        throw IoError(path.string(), "",
                      "a .bzc file is a curve, not a surface (use meshedit eval or info)");
    }
    ReadOptions options;
    options.density = density;
    return read_document(path, options);
}

}  // namespace meshedit::cli
