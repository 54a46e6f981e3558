// C++17 client of fur_bcsdf.h's dual-scattering entry points, driven by
// bcsdf-ffi/tests/c_programs.rs:
//   dual_cpp DUAL_FILE
// Opens the .furdual blob from a std::vector that is destroyed right after (nothing is
// borrowed) into a heap-allocated fur_dual owned by a RAII wrapper, evaluates a few queries
// (fiber counts toward the light and below the point, finite and semi-infinite coats) and
// prints the status and float bits for the Rust test to compare with DualLut bit for bit.
#include "fur_bcsdf.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace {

std::uint32_t bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// Decoded dual-scattering tables on the heap (586 KiB), value-initialised (zeroes, a closed
// fur_dual), closed in the destructor.
class Dual {
public:
    explicit Dual(const std::vector<unsigned char> &bytes) : dual_(new fur_dual()) {
        status_ = fur_dual_open(bytes.data(), bytes.size(), dual_.get());
    }
    ~Dual() { fur_dual_close(dual_.get()); }
    Dual(const Dual &) = delete;
    Dual &operator=(const Dual &) = delete;
    fur_status status() const { return status_; }
    const fur_dual *get() const { return dual_.get(); }

private:
    std::unique_ptr<fur_dual> dual_;
    fur_status status_;
};

constexpr std::array<float, 3> TI{0.5f, -0.3f, 1.2f};
constexpr std::array<float, 3> TR{-0.35f, 0.1f, -1.0f};
constexpr std::array<float, 3> PH{0.785f, 3.0f, -2.0f};

}  // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: dual_cpp DUAL_FILE\n");
        return 2;
    }
    std::unique_ptr<Dual> dual;
    {
        std::ifstream in(argv[1], std::ios::binary);
        std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        dual = std::make_unique<Dual>(bytes);
    }  // the bytes are freed here: the fur_dual owns what it decoded
    if (dual->status() != FUR_OK) {
        std::fprintf(stderr, "open failed: %s\n", fur_status_str(dual->status()));
        return 1;
    }
    const std::array<float, 5> fibers{0.0f, 0.25f, 3.5f, std::numeric_limits<float>::infinity(),
                                      std::numeric_limits<float>::quiet_NaN()};
    // The coat below: on the skin, fractional, finite, semi-infinite (INFINITY and NaN).
    const std::array<float, 5> below{0.0f, 2.5f, 7.0f, std::numeric_limits<float>::infinity(),
                                     std::numeric_limits<float>::quiet_NaN()};
    for (std::size_t i = 0; i < TI.size(); ++i) {
        for (std::size_t f = 0; f < fibers.size(); ++f) {
            for (std::size_t b = 0; b < below.size(); ++b) {
                std::array<float, 3> rgb{};
                fur_status st = fur_eval_dual(dual->get(), TI[i], TR[i], PH[i], fibers[f], below[b], 1.0f,
                                              1.0f, nullptr, rgb.data());
                std::printf("cppdual %zu %zu %zu %d %08x %08x %08x\n", i, f, b, static_cast<int>(st),
                            bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
            }
        }
    }
    const std::array<float, 3> wi{0.3f, 0.8f, 0.2f}, wr{-0.6f, 0.7f, -0.1f}, t{0.0f, 0.2f, 1.0f};
    std::array<float, 3> rgb{};
    for (std::size_t b = 0; b < 4; ++b) {
        fur_status st = fur_eval_dual_dirs(dual->get(), wi.data(), wr.data(), t.data(), 2.0f, below[b], 0.5f,
                                           2.0f, nullptr, rgb.data());
        std::printf("cppdualdirs %zu %d %08x %08x %08x\n", b, static_cast<int>(st), bits(rgb[0]),
                    bits(rgb[1]), bits(rgb[2]));
    }
    // A corrupt blob is refused with its status, the fur_dual left closed.
    std::vector<unsigned char> bad(FUR_DUAL_BLOB_LEN, 0);
    Dual refused(bad);
    if (refused.status() != FUR_ERR_DUAL_FORMAT) return 1;
    if (fur_eval_dual(refused.get(), 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, nullptr, rgb.data()) != FUR_ERR_NOT_OPEN) return 1;
    std::printf("cppdual refused: %s\n", fur_status_str(refused.status()));
    return 0;
}
