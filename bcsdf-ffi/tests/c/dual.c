/*
 * C99 client of fur_bcsdf.h's dual-scattering entry points (fur_dual), driven by
 * bcsdf-ffi/tests/c_programs.rs.
 *
 *   dual DUAL_FILE LUT_FILE OTHER_LUT_FILE
 *
 * Opens DUAL_FILE (a .furdual blob) into a heap-allocated fur_dual, frees the file's bytes
 * (nothing is borrowed), evaluates a fixed set of angles, fiber counts toward the light (0,
 * fractional, large, infinite, NaN, negative), fiber counts below the point (0, fractional,
 * finite, infinite i.e. a semi-infinite coat, NaN, negative, large) and density factors
 * through fur_eval_dual, and a fixed set of directions (degenerate ones included) and counts
 * through fur_eval_dual_dirs, and prints the status and
 * the float bits (hex) for the Rust test to compare with DualLut::eval / eval_dirs bit for
 * bit. Then checks bad input: NULL arguments for every function, misaligned pointers,
 * never-opened (zeroed, FUR_DUAL_INIT, 0xa5-filled), closed and other-build fur_duals,
 * overlapping buffers, corrupt blobs (each refusal status), and 3000 mutated blobs, each of
 * which must be refused. Pairs the fur_dual with fur_luts through fur_dual_check_lut: the LUT
 * the blob was computed from (LUT_FILE), another LUT (OTHER_LUT_FILE), blobs recording another
 * source or none, and closed handles. Prints "dual-bad-input ok" and exits 0 when every check holds.
 * Run plain, under Valgrind memcheck and built with -fsanitize=address,undefined.
 */
#include "fur_bcsdf.h"
#include "client.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The queries the Rust test evaluates too (c_programs.rs: DUAL_* constants). */
#define N_ANGLES 8
static const float TI[N_ANGLES] = {0.5f, -0.3f, 1.2f, 0.0f, -1.5f, 0.25f, 2.0f, 0.4f};
static const float TR[N_ANGLES] = {-0.35f, 0.1f, -1.0f, 0.0f, 1.4f, 0.6f, 0.1f, -0.2f};
static const float PH[N_ANGLES] = {0.785f, 3.0f, -2.0f, 0.0f, 1.0f, -0.1f, 0.3f, 7.0f};
#define N_FIBERS 9
static float FIBERS[N_FIBERS]; /* set in main: INFINITY and NAN are not constant in C99 */
#define N_BELOW 7
static float BELOW[N_BELOW];
#define N_DENSITY 4
static float DF[N_DENSITY];
static float DB[N_DENSITY];
#define N_DIRS 7
static float WI[N_DIRS][3];
static float WR[N_DIRS][3];
static float WT[N_DIRS][3];
#define N_DIR_FIBERS 4
static float DIR_FIBERS[N_DIR_FIBERS];
#define N_DIR_BELOW 4
static float DIR_BELOW[N_DIR_BELOW];

static void set3(float *v, float x, float y, float z) {
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

static void init_queries(void) {
    const float fibers[N_FIBERS] = {0.0f, 0.25f, 1.0f, 2.75f, 40.0f, 1.0e7f, 0.0f, 0.0f, -3.0f};
    memcpy(FIBERS, fibers, sizeof fibers);
    FIBERS[6] = INFINITY;
    FIBERS[7] = NAN;
    /* The coat below: on the skin, fractional, finite, semi-infinite (INFINITY and NaN),
     * negative (0), beyond the largest count (10^6). */
    BELOW[0] = 0.0f;
    BELOW[1] = 2.5f;
    BELOW[2] = 7.0f;
    BELOW[3] = INFINITY;
    BELOW[4] = NAN;
    BELOW[5] = -2.0f;
    BELOW[6] = 1.0e7f;
    DF[0] = 1.0f, DB[0] = 1.0f;
    DF[1] = 0.5f, DB[1] = 2.0f;
    DF[2] = NAN, DB[2] = -1.0f;
    DF[3] = 10.0f, DB[3] = 10.0f;
    /* A regular pair, another, wi along the tangent, a zero wi, a NaN wi, a zero tangent,
     * huge components. */
    set3(WI[0], 0.3f, 0.8f, 0.2f), set3(WR[0], -0.6f, 0.7f, -0.1f), set3(WT[0], 0.0f, 0.2f, 1.0f);
    set3(WI[1], 0.1f, -0.9f, 0.4f), set3(WR[1], 0.5f, 0.5f, 0.5f), set3(WT[1], 1.0f, 0.0f, 0.0f);
    set3(WI[2], 0.0f, 0.0f, 2.0f), set3(WR[2], 0.3f, 0.3f, 0.9f), set3(WT[2], 0.0f, 0.0f, 1.0f);
    set3(WI[3], 0.0f, 0.0f, 0.0f), set3(WR[3], 0.3f, 0.3f, 0.9f), set3(WT[3], 0.0f, 1.0f, 0.0f);
    set3(WI[4], NAN, 0.0f, 1.0f), set3(WR[4], 0.3f, 0.3f, 0.9f), set3(WT[4], 0.0f, 1.0f, 0.0f);
    set3(WI[5], 0.3f, 0.8f, 0.2f), set3(WR[5], -0.6f, 0.7f, -0.1f), set3(WT[5], 0.0f, 0.0f, 0.0f);
    set3(WI[6], 1.0e20f, 1.0e20f, -1.0e20f), set3(WR[6], 0.5f, -0.5f, 0.1f),
        set3(WT[6], 0.0f, 0.0f, 3.0f);
    DIR_FIBERS[0] = 0.0f;
    DIR_FIBERS[1] = 0.5f;
    DIR_FIBERS[2] = 3.0f;
    DIR_FIBERS[3] = NAN;
    DIR_BELOW[0] = 0.0f;
    DIR_BELOW[1] = 2.5f;
    DIR_BELOW[2] = 7.0f;
    DIR_BELOW[3] = INFINITY;
}

#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/* The same address, through a call the compiler does not look into: the overlapping calls
 * below are deliberate, and gcc's -Wrestrict rightly flags the obvious ones. */
static NOINLINE void *opaque(void *p) { return p; }

/* The .furdual checksum: FNV-1a 64 of the blob with its checksum field (bytes 56..64)
 * zeroed, stored little-endian at 56. */
static void reseal(unsigned char *blob, size_t len) {
    unsigned long long h = 0xcbf29ce484222325ULL;
    size_t i;
    for (i = 0; i < len; i++) {
        unsigned char b = (i >= 56 && i < 64) ? 0 : blob[i];
        h = (h ^ b) * 0x100000001b3ULL;
    }
    for (i = 0; i < 8; i++) blob[56 + i] = (unsigned char)(h >> (8 * i));
}

static unsigned long long rng_state = 0x853c49e6748fea9bULL;
static unsigned rng(void) {
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (unsigned)(rng_state >> 33);
}

/* Whether *d is closed: all zeroes. */
static int is_zero(const fur_dual *d) {
    size_t i;
    for (i = 0; i < FUR_DUAL_WORDS; i++)
        if (d->_opaque[i] != 0) return 0;
    return 1;
}

int main(int argc, char **argv) {
    size_t len = 0, i, f, b, k;
    unsigned char *bytes, *copy;
    fur_dual *dual, *other;
    float rgb[3];
    float buf[8];
    float *misaligned = (float *)((char *)buf + 1);
    const float wi[3] = {0.3f, 0.8f, 0.2f}, wr[3] = {-0.6f, 0.7f, -0.1f}, t[3] = {0.0f, 0.2f, 1.0f};
    int refused = 0, m;

    if (argc != 4) {
        fprintf(stderr, "usage: dual DUAL_FILE LUT_FILE OTHER_LUT_FILE\n");
        return 2;
    }
    init_queries();
    bytes = read_file(argv[1], &len);
    /* 586 KiB each: on the heap, zeroed (= FUR_DUAL_INIT). */
    dual = (fur_dual *)calloc(1, sizeof(fur_dual));
    other = (fur_dual *)calloc(1, sizeof(fur_dual));
    copy = bytes ? (unsigned char *)malloc(len + 64) : NULL;
    if (!bytes || !dual || !other || !copy) {
        fprintf(stderr, "cannot read the blob or allocate\n");
        return 2;
    }
    EXPECT(len == FUR_DUAL_BLOB_LEN);
    EXPECT(sizeof(fur_dual) == 600000);
    memcpy(copy, bytes, len);

    /* Open from a heap copy, then free the copy: nothing is borrowed (Valgrind and ASan see
     * any later read of it). */
    {
        unsigned char *heap = (unsigned char *)malloc(len);
        if (!heap) return 2;
        memcpy(heap, bytes, len);
        if (fur_dual_open(heap, len, dual) != FUR_OK) {
            fprintf(stderr, "fur_dual_open failed\n");
            return 1;
        }
        memset(heap, 0xff, len);
        free(heap);
    }

    for (i = 0; i < N_ANGLES; i++)
        for (f = 0; f < N_FIBERS; f++)
            for (b = 0; b < N_BELOW; b++)
                for (k = 0; k < N_DENSITY; k++) {
                    fur_status st;
                    rgb[0] = rgb[1] = rgb[2] = -1.0f;
                    st = fur_eval_dual(dual, TI[i], TR[i], PH[i], FIBERS[f], BELOW[b], DF[k], DB[k], NULL,
                                       rgb);
                    printf("dual %u %u %u %u %d %08x %08x %08x\n", (unsigned)i, (unsigned)f,
                           (unsigned)b, (unsigned)k, (int)st, bits(rgb[0]), bits(rgb[1]),
                           bits(rgb[2]));
                }
    for (i = 0; i < N_DIRS; i++)
        for (f = 0; f < N_DIR_FIBERS; f++)
            for (b = 0; b < N_DIR_BELOW; b++) {
                fur_status st;
                rgb[0] = rgb[1] = rgb[2] = -1.0f;
                st = fur_eval_dual_dirs(dual, WI[i], WR[i], WT[i], DIR_FIBERS[f], DIR_BELOW[b], 1.0f,
                                        1.0f, NULL, rgb);
                printf("dualdirs %u %u %u %d %08x %08x %08x\n", (unsigned)i, (unsigned)f,
                       (unsigned)b, (int)st, bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
            }
    /* A copy made by value is another open fur_dual with the same results. */
    {
        float a[3], b[3];
        memcpy(other, dual, sizeof *dual);
        EXPECT(fur_eval_dual(other, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, NULL, a) == FUR_OK);
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, NULL, b) == FUR_OK);
        EXPECT(memcmp(a, b, sizeof a) == 0);
        EXPECT(a[0] > 0.0f || a[1] > 0.0f || a[2] > 0.0f);
        /* The coat below matters: a point on the skin (0 below) gets less back from it than
         * one over a semi-infinite coat; NaN below is the semi-infinite coat. */
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 0.0f, 1.0f, 1.0f, NULL, a) == FUR_OK);
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, INFINITY, 1.0f, 1.0f, NULL, b) == FUR_OK);
        EXPECT(a[0] < b[0] && a[1] < b[1] && a[2] < b[2]);
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, NAN, 1.0f, 1.0f, NULL, a) == FUR_OK);
        EXPECT(memcmp(a, b, sizeof a) == 0);
        EXPECT(fur_dual_close(other) == FUR_OK);
        EXPECT(is_zero(other));
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, NULL, b) == FUR_OK);
        /* The colour: the preset's own sigma_ca (the blob's header, bytes 64..76) is what
         * NULL evaluates, bit for bit; another colour gives another value; a NaN or negative
         * channel is refused with zeros written. */
        {
            float own[3], dark[3] = {50.0f, 80.0f, 200.0f}, bad[3] = {0.1f, NAN, 0.2f};
            memcpy(own, bytes + 64, sizeof own);
            EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, NULL, a) == FUR_OK);
            EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, own, b) == FUR_OK);
            EXPECT(memcmp(a, b, sizeof a) == 0);
            EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, dark, b) == FUR_OK);
            EXPECT(memcmp(a, b, sizeof a) != 0);
            EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, bad, b) == FUR_ERR_COLOUR &&
                   b[0] == 0.0f && b[1] == 0.0f && b[2] == 0.0f);
            bad[1] = -1.0f;
            EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, bad, b) == FUR_ERR_COLOUR);
        }
    }

    /* NULL arguments for every function. */
    EXPECT(fur_dual_open(NULL, len, other) == FUR_ERR_NULL);
    EXPECT(is_zero(other));
    EXPECT(fur_dual_open(copy, len, NULL) == FUR_ERR_NULL);
    EXPECT(fur_dual_open(copy, 0, other) == FUR_ERR_LENGTH);
    EXPECT(fur_dual_close(NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual(NULL, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual(dual, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual_dirs(NULL, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual_dirs(dual, NULL, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual_dirs(dual, wi, NULL, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual_dirs(dual, wi, wr, NULL, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_dual_dirs(dual, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, NULL) == FUR_ERR_NULL);

    /* Misaligned pointers. */
    EXPECT(fur_eval_dual(dual, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, misaligned) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_eval_dual_dirs(dual, misaligned, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_eval_dual(( const fur_dual *)((const char *)dual + 4), 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f,
                         1.0f, NULL, rgb) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_dual_open(copy, len, (fur_dual *)(void *)((char *)other + 4)) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_dual_close((fur_dual *)(void *)((char *)other + 4)) == FUR_ERR_ALIGNMENT);

    /* Bad angles and directions: 0 written. */
    rgb[0] = -1.0f;
    EXPECT(fur_eval_dual(dual, 2.0f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_ANGLE && rgb[0] == 0.0f);
    rgb[0] = -1.0f;
    EXPECT(fur_eval_dual(dual, 0.1f, 0.2f, INFINITY, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_ANGLE &&
           rgb[0] == 0.0f);
    {
        const float zero[3] = {0.0f, 0.0f, 0.0f};
        rgb[0] = -1.0f;
        EXPECT(fur_eval_dual_dirs(dual, zero, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_DIRECTION &&
               rgb[0] == 0.0f);
    }

    /* Overlapping buffers: the output against the fur_dual and the vectors; open into
     * storage overlapping the bytes. Refused before anything is written. */
    {
        float v[4] = {0.3f, 0.8f, 0.2f, 0.0f};
        unsigned char *big = (unsigned char *)malloc(sizeof(fur_dual) + len);
        EXPECT(fur_eval_dual(dual, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL,
                             (float *)opaque(&dual->_opaque[100])) == FUR_ERR_OVERLAP);
        EXPECT(fur_eval_dual_dirs(dual, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL,
                                  (float *)opaque(&dual->_opaque[FUR_DUAL_WORDS - 1])) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_dual_dirs(dual, v, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, (float *)opaque(v + 1)) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_dual_dirs(dual, wi, wr, v, 1.0f, 2.5f, 1.0f, 1.0f, NULL, (float *)opaque(v + 2)) ==
               FUR_ERR_OVERLAP);
        EXPECT(v[0] == 0.3f && v[1] == 0.8f && v[2] == 0.2f && v[3] == 0.0f);
        if (!big) return 2;
        /* The blob at the end of `big`, the fur_dual at its start, sharing the last bytes. */
        memcpy(big + sizeof(fur_dual) - 8, bytes, len);
        EXPECT(fur_dual_open(big + sizeof(fur_dual) - 8, len, (fur_dual *)(void *)big) == FUR_ERR_OVERLAP);
        EXPECT(memcmp(big + sizeof(fur_dual) - 8, bytes, len) == 0);
        free(big);
        /* The fur_dual still evaluates. */
        EXPECT(fur_eval_dual(dual, TI[0], TR[0], PH[0], 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_OK);
    }

    /* Never opened: calloc'd, FUR_DUAL_INIT, 0xa5-filled. */
    memset(other, 0, sizeof *other);
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    {
        static fur_dual init = FUR_DUAL_INIT;
        EXPECT(fur_eval_dual(&init, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_eval_dual_dirs(&init, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    }
    memset(other, 0xa5, sizeof *other);
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_eval_dual_dirs(other, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);

    /* Another build's fur_dual: word 1 holds the build tag; a changed check word (3) or
     * source (2) is not an open fur_dual. */
    memcpy(other, dual, sizeof *dual);
    other->_opaque[1] ^= 1u;
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_OTHER_BUILD);
    EXPECT(fur_eval_dual_dirs(other, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_OTHER_BUILD);
    other->_opaque[1] ^= 1u;
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_OK);
    other->_opaque[3] ^= 1u;
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    other->_opaque[3] ^= 1u;
    other->_opaque[2] ^= 1u;
    EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_dual_close(other) == FUR_OK);
    EXPECT(is_zero(other));

    /* Corrupt blobs: each refusal status, and the fur_dual left closed (zeroes) even when it
     * was open before. */
#define REFUSED(n, status)                                      \
    do {                                                        \
        memcpy(other, dual, sizeof *dual);                      \
        EXPECT(fur_dual_open(copy, (n), other) == (status));    \
        EXPECT(is_zero(other));                                 \
        EXPECT(fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN); \
        memcpy(copy, bytes, len);                               \
    } while (0)
    REFUSED(len - 1, FUR_ERR_DUAL_LENGTH);
    REFUSED(len + 1, FUR_ERR_DUAL_LENGTH);
    REFUSED(7, FUR_ERR_DUAL_LENGTH);
    copy[0] ^= 0x20; /* "fURDUAL" */
    REFUSED(len, FUR_ERR_DUAL_FORMAT);
    copy[8] += 1; /* the format version */
    REFUSED(len, FUR_ERR_DUAL_VERSION);
    copy[12] += 1; /* the model version */
    REFUSED(len, FUR_ERR_DUAL_VERSION);
    copy[16] += 1; /* the theta node count */
    REFUSED(len, FUR_ERR_DUAL_INVALID);
    copy[32] = 9; /* the attenuation */
    REFUSED(len, FUR_ERR_DUAL_INVALID);
    copy[1000] ^= 1; /* a value's bit */
    REFUSED(len, FUR_ERR_DUAL_CHECKSUM);
    copy[60] ^= 0x80; /* the checksum itself */
    REFUSED(len, FUR_ERR_DUAL_CHECKSUM);
    /* A NaN half (0x7e00, little-endian) in the first field, resealed: the checksum holds,
     * the value check refuses it. Then a positive log2 of the decay (1.0 = 0x3c00). */
    copy[80] = 0x00, copy[81] = 0x7e;
    reseal(copy, len);
    REFUSED(len, FUR_ERR_DUAL_INVALID);
    copy[80] = 0x00, copy[81] = 0x3c;
    reseal(copy, len);
    REFUSED(len, FUR_ERR_DUAL_INVALID);
    /* A NaN preset colour (sigma_ca R, f32 at bytes 64..68), resealed. */
    copy[66] = 0xc0, copy[67] = 0x7f;
    reseal(copy, len);
    REFUSED(len, FUR_ERR_DUAL_INVALID);
    /* The unchanged copy opens (the reseal is right), and evaluates like the first. */
    reseal(copy, len);
    EXPECT(memcmp(copy, bytes, len) == 0);
    EXPECT(fur_dual_open(copy, len, other) == FUR_OK);
    EXPECT(fur_eval_dual(other, TI[0], TR[0], PH[0], 2.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_OK);
    EXPECT(fur_dual_close(other) == FUR_OK);

    /* Pairing with LUTs (fur_dual_check_lut): the LUT the blob was computed from, another
     * LUT, blobs that record another source (bytes 40..48) or none, closed handles. */
    {
        size_t lut_len = 0, other_len = 0;
        unsigned char *lut_bytes = read_file(argv[2], &lut_len);
        unsigned char *other_bytes = read_file(argv[3], &other_len);
        fur_lut lut = FUR_LUT_INIT, other_lut = FUR_LUT_INIT, never = FUR_LUT_INIT;
        if (!lut_bytes || !other_bytes) {
            fprintf(stderr, "cannot read the LUT files\n");
            return 2;
        }
        EXPECT(fur_lut_open(lut_bytes, lut_len, &lut) == FUR_OK);
        EXPECT(fur_lut_open(other_bytes, other_len, &other_lut) == FUR_OK);
        EXPECT(fur_dual_check_lut(dual, &lut) == FUR_OK);
        EXPECT(fur_dual_check_lut(dual, &other_lut) == FUR_ERR_DUAL_SOURCE);
        copy[44] ^= 0x10; /* another source, resealed: opens, pairs with neither */
        reseal(copy, len);
        EXPECT(fur_dual_open(copy, len, other) == FUR_OK);
        EXPECT(fur_dual_check_lut(other, &lut) == FUR_ERR_DUAL_SOURCE);
        EXPECT(fur_dual_check_lut(other, &other_lut) == FUR_ERR_DUAL_SOURCE);
        memset(copy + 40, 0, 8); /* no source recorded */
        reseal(copy, len);
        EXPECT(fur_dual_open(copy, len, other) == FUR_OK);
        EXPECT(fur_dual_check_lut(other, &lut) == FUR_ERR_DUAL_SOURCE);
        EXPECT(fur_dual_close(other) == FUR_OK);
        memcpy(copy, bytes, len);
        EXPECT(fur_dual_check_lut(other, &lut) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_dual_check_lut(dual, &never) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_dual_check_lut(NULL, &lut) == FUR_ERR_NULL);
        EXPECT(fur_dual_check_lut(dual, NULL) == FUR_ERR_NULL);
        EXPECT(fur_dual_check_lut(dual, (const fur_lut *)(const void *)((const char *)&lut + 4)) ==
               FUR_ERR_ALIGNMENT);
        EXPECT(fur_lut_close(&lut) == FUR_OK);
        EXPECT(fur_dual_check_lut(dual, &lut) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_lut_close(&other_lut) == FUR_OK);
        free(other_bytes);
        free(lut_bytes);
    }

    for (m = FUR_ERR_DUAL_LENGTH; m <= FUR_ERR_DUAL_SOURCE; m++) {
        const char *s = fur_status_str(m);
        EXPECT(strcmp(s, "unknown status") != 0 && strstr(s, "dual") != NULL);
    }

    /* 3000 mutated blobs: one bit flipped, truncated, or with bytes appended. */
    for (m = 0; m < 3000; m++) {
        size_t n = len;
        fur_status st;
        memcpy(copy, bytes, len);
        switch (m % 3) {
        case 0:
            copy[rng() % len] ^= (unsigned char)(1u << (rng() % 8));
            break;
        case 1:
            n = rng() % len;
            break;
        default:
            n = len + 1 + rng() % 63;
            for (i = len; i < n; i++) copy[i] = (unsigned char)rng();
            break;
        }
        st = fur_dual_open(copy, n, other);
        if (st >= FUR_ERR_DUAL_LENGTH && st <= FUR_ERR_DUAL_INVALID &&
            fur_eval_dual(other, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN)
            refused++;
        else if (n == 0 && st == FUR_ERR_LENGTH)
            refused++;
    }
    EXPECT(refused == 3000);
    printf("dual mutated refused %d of 3000\n", refused);

    /* Closed: refused, and reads nothing else. */
    EXPECT(fur_dual_close(dual) == FUR_OK);
    EXPECT(is_zero(dual));
    EXPECT(fur_eval_dual(dual, 0.1f, 0.2f, 0.3f, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_eval_dual_dirs(dual, wi, wr, t, 1.0f, 2.5f, 1.0f, 1.0f, NULL, rgb) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_dual_close(dual) == FUR_OK);

    free(copy);
    free(bytes);
    free(other);
    free(dual);
    if (failures) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    printf("dual-bad-input ok\n");
    return 0;
}
