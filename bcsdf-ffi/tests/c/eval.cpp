// C++17 client of fur_bcsdf.h, driven by bcsdf-ffi/tests/c_programs.rs:
//   eval_cpp LUT_FILE
// Opens the LUT from a std::vector, evaluates the same directions as eval.c, at the LUT's own
// colour and through the colour (_at) entry points at four colours, and prints the float bits
// for the Rust test to compare with BakedBcsdf bit for bit.
#include "fur_bcsdf.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

namespace {

std::uint32_t bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// A LUT opened on bytes this object owns (the fur_lut borrows them): closed in the
// destructor, before the members (the bytes) are destroyed, as the header's contract asks.
class Lut {
public:
    explicit Lut(std::vector<unsigned char> bytes) : bytes_(std::move(bytes)) {
        status_ = fur_lut_open(bytes_.data(), bytes_.size(), &lut_);
    }
    ~Lut() { fur_lut_close(&lut_); }
    Lut(const Lut &) = delete;
    Lut &operator=(const Lut &) = delete;
    fur_status status() const { return status_; }
    const fur_lut *get() const { return &lut_; }

private:
    std::vector<unsigned char> bytes_;
    fur_lut lut_ = FUR_LUT_INIT;
    fur_status status_;
};

constexpr std::array<float, 6> TI{0.5f, -0.3f, 1.2f, 0.0f, -1.5f, 0.25f};
constexpr std::array<float, 6> TR{-0.35f, 0.1f, -1.0f, 0.0f, 1.4f, 0.6f};
constexpr std::array<float, 6> PH{0.785f, 3.0f, -2.0f, 0.0f, 1.0f, -0.1f};

}  // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: eval_cpp LUT_FILE\n");
        return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Lut lut(std::move(bytes));
    if (lut.status() != FUR_OK) {
        std::fprintf(stderr, "open failed: %s\n", fur_status_str(lut.status()));
        return 1;
    }
    for (std::size_t i = 0; i < TI.size(); ++i) {
        std::array<float, 3> rgb{};
        if (fur_eval_far(lut.get(), TI[i], TR[i], PH[i], rgb.data()) != FUR_OK) return 1;
        std::printf("eval %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
    }
    fur_sample s{};
    if (fur_sample_far(lut.get(), 0.3f, 0.2f, 0.4f, 0.6f, &s) != FUR_OK) return 1;
    std::printf("sample %08x %08x %08x %d\n", bits(s.theta_i), bits(s.phi), bits(s.pdf),
                static_cast<int>(s.family));
    float p = 0.0f;
    if (fur_sample_pdf_far(lut.get(), 0.3f, 0.2f, 0.4f, 0.6f, TI[0], PH[0], &s, &p) != FUR_OK) return 1;
    std::printf("samplepdf %08x %08x %08x %d %08x\n", bits(s.theta_i), bits(s.phi), bits(s.pdf),
                static_cast<int>(s.family), bits(p));
    // Colours: the LUT's own, lossless, a red-brown one, and melanin's.
    std::array<std::array<float, 3>, 4> colours{};
    if (fur_lut_sigma_ca(lut.get(), colours[0].data()) != FUR_OK) return 1;
    colours[2] = {0.5f, 2.0f, 150.0f};
    if (fur_sigma_from_melanin(0.4f, 1.5f, colours[3].data()) != FUR_OK) return 1;
    for (std::size_t c = 0; c < colours.size(); ++c) {
        for (std::size_t i = 0; i < TI.size(); ++i) {
            std::array<float, 3> rgb{};
            if (fur_eval_far_at(lut.get(), colours[c].data(), TI[i], TR[i], PH[i], rgb.data()) != FUR_OK) return 1;
            std::printf("evalat %zu %08x %08x %08x\n", c, bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
        }
        if (fur_sample_far_at(lut.get(), colours[c].data(), 0.3f, 0.2f, 0.4f, 0.6f, &s) != FUR_OK) return 1;
        std::printf("sampleat %zu %08x %08x %08x %08x %08x %08x\n", c, bits(s.theta_i), bits(s.phi),
                    bits(s.pdf), bits(s.weight[0]), bits(s.weight[1]), bits(s.weight[2]));
    }
    const std::array<float, 3> nan_colour{0.5f, std::numeric_limits<float>::quiet_NaN(), 0.5f};
    std::array<float, 3> rgb{};
    if (fur_eval_far_at(lut.get(), nan_colour.data(), TI[0], TR[0], PH[0], rgb.data()) != FUR_ERR_COLOUR) return 1;
    std::printf("refused: %s\n", fur_status_str(FUR_ERR_COLOUR));
    return 0;
}
