/* The README's C example ("Embedding from C or C++"), compiled by tests/c_programs.rs. */
#include "fur_bcsdf.h"   /* cc -std=c99 app.c -Ibcsdf-ffi/include target/release/libbcsdf_ffi.a -lpthread -ldl -lm */
#include <stdio.h>

int shade(const unsigned char *bytes, size_t len) {   /* bytes: a .furlut, kept alive */
    fur_lut lut = FUR_LUT_INIT;                      /* fixed size: stack, arena or member */
    fur_sample s;
    float rgb[3];
    fur_status st = fur_lut_open(bytes, len, &lut);  /* validates; borrows the bytes */
    if (st != FUR_OK) {
        fprintf(stderr, "LUT refused: %s\n", fur_status_str(st));
        return -1;
    }
    fur_eval_far(&lut, 0.5f, -0.35f, 0.785f, rgb);   /* theta_i, theta_r, phi (radians) */
    if (fur_sample_far(&lut, -0.35f, 0.2f, 0.4f, 0.6f, &s) == FUR_OK)
        printf("omega_i (%g, %g), pdf %g, weight %g\n", s.theta_i, s.phi, s.pdf, s.weight[0]);
    printf("S = %g %g %g, pdf %g\n", rgb[0], rgb[1], rgb[2],
           fur_pdf_far(&lut, 0.5f, -0.35f, 0.785f));
    fur_lut_close(&lut);                             /* before the bytes are freed */
    return 0;
}

int main(void) {
    static const unsigned char not_a_lut[4] = {1, 2, 3, 4};
    return shade(not_a_lut, sizeof not_a_lut) == -1 ? 0 : 1;
}
