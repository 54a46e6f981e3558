/* A program that uses the installed C library (README "Installing the C library"): built by
 * CMake with find_package(fur_bcsdf) (CMakeLists.txt beside it) and by
 *   cc consumer.c $(pkg-config --cflags --libs fur_bcsdf)
 * It opens the .furlut given on the command line and prints the far-field S at
 * (theta_i, theta_r, phi) in radians as the bits of R, G and B in hex, the line that
 * `cargo run -p bcsdf-ffi --example eval_far` prints from Rust. */
#include <fur_bcsdf.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned char *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    unsigned char *bytes = NULL;
    long size;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) > 0 && fseek(f, 0, SEEK_SET) == 0) {
        bytes = malloc((size_t)size); /* malloc's alignment suits fur_lut_open */
        if (bytes && fread(bytes, 1, (size_t)size, f) != (size_t)size) {
            free(bytes);
            bytes = NULL;
        }
        *len = (size_t)size;
    }
    fclose(f);
    return bytes;
}

int main(int argc, char **argv) {
    fur_lut lut;
    float rgb[3];
    uint32_t bits[3];
    size_t len = 0, i;
    unsigned char *bytes;
    fur_status st;
    if (argc != 5) {
        fprintf(stderr, "usage: %s LUT THETA_I THETA_R PHI (radians)\n", argv[0]);
        return 2;
    }
    bytes = read_file(argv[1], &len);
    if (!bytes) {
        fprintf(stderr, "error: %s: cannot read the file\n", argv[1]);
        return 1;
    }
    st = fur_lut_open(bytes, len, &lut);
    if (st == FUR_OK)
        st = fur_eval_far(&lut, strtof(argv[2], NULL), strtof(argv[3], NULL),
                          strtof(argv[4], NULL), rgb);
    if (st != FUR_OK) {
        fprintf(stderr, "error: %s: %s\n", argv[1], fur_status_str(st));
        free(bytes);
        return 1;
    }
    for (i = 0; i < 3; i++) memcpy(&bits[i], &rgb[i], sizeof bits[i]);
    printf("S %08x %08x %08x\n", (unsigned)bits[0], (unsigned)bits[1], (unsigned)bits[2]);
    fur_lut_close(&lut);
    free(bytes);
    return 0;
}
