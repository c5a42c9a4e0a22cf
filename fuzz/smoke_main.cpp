// A standalone driver for a fuzz target's LLVMFuzzerTestOneInput, so that every target gets a
// short, deterministic smoke run in the normal build (ctest FuzzSmoke.*) without clang or
// libFuzzer. It replays a target's starting corpus, then mutants of those inputs (bit flips, byte
// insertions and deletions, truncations, splices of two inputs, repeated ranges, extreme integers
// and, for text targets, dictionary tokens, repeated brackets and extreme numbers), until a time
// or a count limit. A crash kills the process, which fails the test; the count of inputs run is
// printed.
//
//   fuzz_smoke_<target> [--seconds S] [--max-inputs N] [--text] [--dict FILE]
//                       [--crash-file FILE] SEED...
//
// A SEED is a file or a folder (read recursively, in name order). On a crash the input is written
// to the crash file (default fuzz-smoke-crash.bin in the working folder) before the process dies.
#include <fcntl.h>
#include <unistd.h>
#include <algorithm>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

// splitmix64: a small, fixed generator, so every run tries the same mutants in the same order.
struct Random {
    std::uint64_t state = 0x6c7578656c66757aull;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

Bytes readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void addSeeds(const std::filesystem::path& path, std::vector<Bytes>& seeds) {
    if (std::filesystem::is_directory(path)) {
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
            if (entry.is_regular_file()) files.push_back(entry.path());
        }
        std::sort(files.begin(), files.end());
        for (const auto& file : files) seeds.push_back(readFile(file));
    } else if (std::filesystem::is_regular_file(path)) {
        seeds.push_back(readFile(path));
    } else {
        std::fprintf(stderr, "fuzz smoke: no seed file or folder '%s'\n", path.c_str());
        std::exit(2);
    }
}

// libFuzzer's dictionary format: one "token" per line (optionally name="token"), with \\, \" and
// \xNN escapes; '#' starts a comment.
std::vector<Bytes> readDictionary(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "fuzz smoke: cannot read dictionary '%s'\n", path.c_str());
        std::exit(2);
    }
    std::vector<Bytes> tokens;
    for (std::string line; std::getline(in, line);) {
        const std::size_t open = line.find('"');
        const std::size_t close = line.rfind('"');
        if (line.empty() || line[0] == '#' || open == std::string::npos || close <= open) continue;
        Bytes token;
        for (std::size_t i = open + 1; i < close; ++i) {
            if (line[i] == '\\' && i + 1 < close && line[i + 1] == 'x' && i + 3 < close) {
                token.push_back(
                    static_cast<std::uint8_t>(std::stoi(line.substr(i + 2, 2), nullptr, 16)));
                i += 3;
            } else if (line[i] == '\\' && i + 1 < close) {
                token.push_back(static_cast<std::uint8_t>(line[++i]));
            } else {
                token.push_back(static_cast<std::uint8_t>(line[i]));
            }
        }
        if (!token.empty()) tokens.push_back(std::move(token));
    }
    return tokens;
}

Bytes asBytes(const char* text) {
    return Bytes(text, text + std::char_traits<char>::length(text));
}

class Mutator {
  public:
    Mutator(const std::vector<Bytes>& seeds, std::vector<Bytes> tokens, bool text)
        : seeds_(seeds), tokens_(std::move(tokens)), text_(text) {
        for (const char* t : {"{", "}", "[", "]", "\"", ",", ":", "\n", " ", "null", "-1", "0"}) {
            tokens_.push_back(asBytes(t));
        }
    }

    // One to three stacked mutations of a random seed.
    Bytes next() {
        Bytes b = seeds_[random_.below(seeds_.size())];
        const std::size_t count = 1 + random_.below(3);
        for (std::size_t i = 0; i < count; ++i) mutate(b);
        return b;
    }

  private:
    void mutate(Bytes& b) {
        const std::size_t kinds = text_ ? 12 : 8;
        switch (random_.below(kinds)) {
            case 0:  // flip one bit
                if (!b.empty()) b[random_.below(b.size())] ^= std::uint8_t(1u << random_.below(8));
                break;
            case 1:  // an interesting byte
                if (!b.empty()) {
                    static const std::uint8_t kBytes[] = {0, 1, 0x7f, 0x80, 0xff, '"', '\n', '\\'};
                    b[random_.below(b.size())] = kBytes[random_.below(std::size(kBytes))];
                }
                break;
            case 2:  // insert a random byte
                b.insert(b.begin() + static_cast<long>(random_.below(b.size() + 1)),
                         static_cast<std::uint8_t>(random_.next()));
                break;
            case 3: {  // delete a short range
                if (b.empty()) break;
                const std::size_t at = random_.below(b.size());
                const std::size_t n = std::min(b.size() - at, 1 + random_.below(8));
                b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
                break;
            }
            case 4:  // truncate
                b.resize(random_.below(b.size() + 1));
                break;
            case 5: {  // splice: the start of this input, the end of another seed
                const Bytes& other = seeds_[random_.below(seeds_.size())];
                const std::size_t cut = random_.below(b.size() + 1);
                const std::size_t from = random_.below(other.size() + 1);
                b.resize(cut);
                b.insert(b.end(), other.begin() + static_cast<long>(from), other.end());
                break;
            }
            case 6: {  // copy a range elsewhere, possibly many times (repeated chunks, lists)
                if (b.empty()) break;
                const std::size_t at = random_.below(b.size());
                const std::size_t n = std::min(b.size() - at, 1 + random_.below(64));
                const Bytes range(b.begin() + static_cast<long>(at),
                                  b.begin() + static_cast<long>(at + n));
                const std::size_t times = random_.below(4) == 0 ? 1 + random_.below(200) : 1;
                const std::size_t to = random_.below(b.size() + 1);
                for (std::size_t i = 0; i < times && b.size() < (1u << 20); ++i) {
                    b.insert(b.begin() + static_cast<long>(to), range.begin(), range.end());
                }
                break;
            }
            case 7: {  // an extreme 32-bit integer, either byte order (sizes, counts, offsets)
                if (b.size() < 4) break;
                static const std::uint32_t kValues[] = {
                    0, 1, 0x7fffffffu, 0x80000000u, 0xffffffffu, 0x10000u, 4096, 257};
                const std::uint32_t v = kValues[random_.below(std::size(kValues))];
                const std::size_t at = random_.below(b.size() - 3);
                const bool big = random_.below(2) == 0;
                for (int i = 0; i < 4; ++i) {
                    b[at + static_cast<std::size_t>(i)] =
                        static_cast<std::uint8_t>(v >> (8 * (big ? 3 - i : i)));
                }
                break;
            }
            case 8: {  // insert a dictionary token
                const Bytes& t = tokens_[random_.below(tokens_.size())];
                b.insert(b.begin() + static_cast<long>(random_.below(b.size() + 1)), t.begin(),
                         t.end());
                break;
            }
            case 9: {  // repeat an opening or closing bracket (deep nesting, unbalanced text)
                std::vector<std::size_t> at;
                for (std::size_t i = 0; i < b.size(); ++i) {
                    if (b[i] == '[' || b[i] == '{' || b[i] == ']' || b[i] == '}') at.push_back(i);
                }
                if (at.empty()) break;
                const std::size_t i = at[random_.below(at.size())];
                const std::size_t times = 1 + random_.below(random_.below(2) == 0 ? 4 : 400);
                const std::uint8_t bracket = b[i];
                b.insert(b.begin() + static_cast<long>(i), times, bracket);
                break;
            }
            case 10: {  // delete one bracket, quote, comma or colon
                std::vector<std::size_t> at;
                for (std::size_t i = 0; i < b.size(); ++i) {
                    if (std::string_view("[]{}\",:").find(static_cast<char>(b[i])) !=
                        std::string_view::npos) {
                        at.push_back(i);
                    }
                }
                if (!at.empty())
                    b.erase(b.begin() + static_cast<long>(at[random_.below(at.size())]));
                break;
            }
            case 11: {  // replace a number by an extreme one
                std::vector<std::size_t> starts;
                for (std::size_t i = 0; i < b.size(); ++i) {
                    const bool digit = b[i] >= '0' && b[i] <= '9';
                    const bool after = i > 0 && ((b[i - 1] >= '0' && b[i - 1] <= '9') ||
                                                 b[i - 1] == '.' || b[i - 1] == '-');
                    if (digit && !after) starts.push_back(i);
                }
                if (starts.empty()) break;
                const std::size_t s = starts[random_.below(starts.size())];
                std::size_t e = s;
                while (e < b.size() &&
                       std::string_view("0123456789.eE+-").find(static_cast<char>(b[e])) !=
                           std::string_view::npos) {
                    ++e;
                }
                static const char* const kNumbers[] = {"1e308",  "-1e308", "1e999", "-0",
                                                       "0",      "4097",   "65537", "2147483648",
                                                       "1e-320", "0.5",    "-1",    "99999999999"};
                const Bytes n = asBytes(kNumbers[random_.below(std::size(kNumbers))]);
                b.erase(b.begin() + static_cast<long>(s), b.begin() + static_cast<long>(e));
                b.insert(b.begin() + static_cast<long>(s), n.begin(), n.end());
                break;
            }
        }
    }

    const std::vector<Bytes>& seeds_;
    std::vector<Bytes> tokens_;
    bool text_;
    Random random_;
};

// The input being run, written out by the signal handler when the target crashes, so the crash
// can be replayed (fuzz_smoke_<target> FILE, or the libFuzzer binary on it).
const Bytes* gCurrent = nullptr;
const char* gCrashFile = "fuzz-smoke-crash.bin";

extern "C" void onCrash(int signal) {
    if (gCurrent != nullptr) {
        const int fd = ::open(gCrashFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            const ssize_t written = ::write(fd, gCurrent->data(), gCurrent->size());
            (void)written;
            ::close(fd);
        }
        static const char kNote[] = "fuzz smoke: the target crashed; the input is in ";
        ssize_t w = ::write(2, kNote, sizeof kNote - 1);
        w = ::write(2, gCrashFile, std::strlen(gCrashFile));
        w = ::write(2, "\n", 1);
        (void)w;
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void run(const Bytes& input) {
    gCurrent = &input;
    LLVMFuzzerTestOneInput(input.data(), input.size());
    gCurrent = nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 3.0;
    std::size_t maxInputs = 100000;
    bool text = false;
    std::vector<Bytes> tokens;
    std::vector<Bytes> seeds;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else if (arg == "--max-inputs" && i + 1 < argc) {
            maxInputs = static_cast<std::size_t>(std::atoll(argv[++i]));
        } else if (arg == "--text") {
            text = true;
        } else if (arg == "--crash-file" && i + 1 < argc) {
            gCrashFile = argv[++i];
        } else if (arg == "--dict" && i + 1 < argc) {
            tokens = readDictionary(argv[++i]);
        } else {
            addSeeds(arg, seeds);
        }
    }
    if (seeds.empty()) {
        std::fprintf(stderr, "fuzz smoke: no seeds given\n");
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    std::size_t ran = 0;
    for (int signal : {SIGSEGV, SIGILL, SIGABRT, SIGBUS, SIGFPE}) std::signal(signal, onCrash);
    for (const Bytes& seed : seeds) {
        run(seed);
        ++ran;
    }
    Mutator mutator(seeds, std::move(tokens), text);
    std::size_t mutants = 0;
    while (ran < maxInputs && elapsed() < seconds) {
        const Bytes input = mutator.next();
        run(input);
        ++ran;
        ++mutants;
    }
    std::printf("fuzz smoke: %zu inputs (%zu seeds, %zu mutants) in %.2f s, no crash\n", ran,
                seeds.size(), mutants, elapsed());
    return 0;
}
