/*
 * C99 client of fur_bcsdf.h, driven by bcsdf-ffi/tests/c_programs.rs.
 *
 *   eval LUT_FILE SMALL_LUT_FILE
 *
 * Opens LUT_FILE, evaluates a fixed set of directions through every evaluation entry point
 * and prints the float bits (hex) for the Rust test to compare with BakedBcsdf bit for bit;
 * the same through every colour (_at) entry point at the LUT's own colour and at
 * N_COLOURS pseudo-random ones (random_colour; the Rust test draws the same);
 * then checks bad input: NULL and zero-length arguments for every function, misaligned
 * pointers, zeroed and FUR_LUT_INIT-initialised fur_luts that were never opened, a fur_lut
 * used after close and after its bytes were freed, a fur_lut of another build, overlapping
 * buffers, and 100 000 mutated copies of SMALL_LUT_FILE (bit flips, truncations, appends),
 * each of which must be refused. Prints "bad-input ok" and exits 0 when every check holds.
 * Run plain, under Valgrind memcheck and built with -fsanitize=address,undefined.
 */
#include "fur_bcsdf.h"
#include "client.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The directions the Rust test evaluates too (radians). */
#define N_DIRS 6
static const float TI[N_DIRS] = {0.5f, -0.3f, 1.2f, 0.0f, -1.5f, 0.25f};
static const float TR[N_DIRS] = {-0.35f, 0.1f, -1.0f, 0.0f, 1.4f, 0.6f};
static const float PH[N_DIRS] = {0.785f, 3.0f, -2.0f, 0.0f, 1.0f, -0.1f};

#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#else
#define NOINLINE
#endif

/*
 * The use-after-free sequence of the handle contract: open_then_close opens a
 * fur_lut on heap bytes and closes it before returning (the caller then frees the bytes);
 * eval_fresh's fur_lut, in the same stack slot, is initialised with FUR_LUT_INIT and refused.
 * Without the close and the initialiser this read freed memory (SIGSEGV at -O0).
 */
static NOINLINE fur_status open_then_close(const unsigned char *bytes, size_t len) {
    fur_lut l = FUR_LUT_INIT;
    fur_status st = fur_lut_open(bytes, len, &l);
    if (fur_lut_close(&l) != FUR_OK) return FUR_ERR_NULL;
    return st;
}

static NOINLINE fur_status eval_fresh(float *rgb) {
    fur_lut l = FUR_LUT_INIT;
    return fur_eval_far(&l, 0.1f, 0.2f, 0.3f, rgb);
}

/* The same address, through a call the compiler does not look into: the overlapping calls
 * below are deliberate, and gcc's -Wrestrict rightly flags the obvious ones. */
static NOINLINE void *opaque(void *p) { return p; }

/*
 * The colours of the _at calls: sigma_ca per channel from a 64-bit LCG (the Rust test repeats
 * it): kind (r >> 16) & 7 picks 0, [100, 1000), [1000, 5000) (clamped to 1000 by the
 * library), or u times 0.01, 0.1, 1, 4 or 20, u = (r & 0xffff) / 65536.
 */
#define N_COLOURS 24
static unsigned long long colour_state = 0x2545f4914f6cdd1dULL;
static float colour_channel(void) {
    static const float scale[5] = {0.01f, 0.1f, 1.0f, 4.0f, 20.0f};
    unsigned r, kind;
    float u;
    colour_state = colour_state * 6364136223846793005ULL + 1442695040888963407ULL;
    r = (unsigned)(colour_state >> 33);
    kind = (r >> 16) & 7u;
    u = (float)(r & 0xffffu) * (1.0f / 65536.0f);
    if (kind == 0u) return 0.0f;
    if (kind == 1u) return 100.0f + 900.0f * u;
    if (kind == 2u) return 1000.0f + 4000.0f * u;
    return u * scale[kind - 3u];
}

static void print_sample(const char *name, const fur_sample *s) {
    printf("%s %08x %08x %08x %08x %08x %08x %d", name, bits(s->theta_i), bits(s->phi), bits(s->pdf),
           bits(s->weight[0]), bits(s->weight[1]), bits(s->weight[2]), (int)s->family);
}

static unsigned long long rng_state = 0x853c49e6748fea9bULL;
static unsigned rng(void) {
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (unsigned)(rng_state >> 33);
}

int main(int argc, char **argv) {
    size_t len = 0, small_len = 0, i;
    unsigned char *bytes, *small, *copy;
    fur_lut lut = FUR_LUT_INIT, never = FUR_LUT_INIT, foreign;
    fur_sample s;
    float rgb[3], fam[12], batch[3 * N_DIRS];
    const float wi[3] = {0.3f, 0.8f, 0.2f}, wr[3] = {-0.6f, 0.7f, -0.1f}, t[3] = {0.0f, 0.2f, 1.0f};
    float buf[8];
    float *misaligned = (float *)((char *)buf + 1);
    int k, k2, refused = 0;

    if (argc != 3) {
        fprintf(stderr, "usage: eval LUT_FILE SMALL_LUT_FILE\n");
        return 2;
    }
    bytes = read_file(argv[1], &len);
    small = read_file(argv[2], &small_len);
    if (!bytes || !small) {
        fprintf(stderr, "cannot read the LUT files\n");
        return 2;
    }
    printf("version %s format %u model %u\n", fur_version(), fur_lut_format_version(),
           fur_model_version());
    if (fur_lut_open(bytes, len, &lut) != FUR_OK) {
        fprintf(stderr, "open failed\n");
        return 1;
    }

    for (i = 0; i < N_DIRS; i++) {
        EXPECT(fur_eval_far(&lut, TI[i], TR[i], PH[i], rgb) == FUR_OK);
        printf("eval %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
        EXPECT(fur_eval_far_families(&lut, TI[i], TR[i], PH[i], fam) == FUR_OK);
        printf("families");
        for (k = 0; k < 12; k++) printf(" %08x", bits(fam[k]));
        printf("\n");
        printf("pdf %08x\n", bits(fur_pdf_far(&lut, TI[i], TR[i], PH[i])));
    }
    EXPECT(fur_eval_far_batch(&lut, N_DIRS, TI, TR, PH, batch) == FUR_OK);
    printf("batch");
    for (k = 0; k < 3 * N_DIRS; k++) printf(" %08x", bits(batch[k]));
    printf("\n");
    EXPECT(fur_eval_far_dirs(&lut, wi, wr, t, rgb) == FUR_OK);
    printf("dirs %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
    for (i = 0; i < N_DIRS; i++) {
        fur_status st = fur_sample_far(&lut, TR[i], 0.1f + 0.15f * (float)i, 0.9f - 0.1f * (float)i, 0.37f, &s);
        EXPECT(st == FUR_OK);
        printf("sample %08x %08x %08x %08x %08x %08x %d\n", bits(s.theta_i), bits(s.phi), bits(s.pdf),
               bits(s.weight[0]), bits(s.weight[1]), bits(s.weight[2]), (int)s.family);
    }
    for (i = 0; i < N_DIRS; i++) {
        /* A sample and the density of another direction (a light's) at the same view. */
        float p = -1.0f;
        fur_status st = fur_sample_pdf_far(&lut, TR[i], 0.1f + 0.15f * (float)i, 0.9f - 0.1f * (float)i,
                                           0.37f, TI[i], PH[i], &s, &p);
        EXPECT(st == FUR_OK);
        printf("samplepdf %08x %08x %08x %08x %08x %08x %d %08x\n", bits(s.theta_i), bits(s.phi),
               bits(s.pdf), bits(s.weight[0]), bits(s.weight[1]), bits(s.weight[2]), (int)s.family,
               bits(p));
    }

    /* Colours. The LUT's own: every _at function equals its sibling without _at. */
    {
        float own[3], a[12], b[12], pa, pb;
        fur_sample sa, sb;
        EXPECT(fur_lut_sigma_ca(&lut, own) == FUR_OK);
        printf("own %08x %08x %08x\n", bits(own[0]), bits(own[1]), bits(own[2]));
        for (i = 0; i < N_DIRS; i++) {
            EXPECT(fur_eval_far_at(&lut, own, TI[i], TR[i], PH[i], a) == FUR_OK);
            EXPECT(fur_eval_far(&lut, TI[i], TR[i], PH[i], b) == FUR_OK);
            EXPECT(memcmp(a, b, 3 * sizeof(float)) == 0);
            EXPECT(fur_eval_far_families_at(&lut, own, TI[i], TR[i], PH[i], a) == FUR_OK);
            EXPECT(fur_eval_far_families(&lut, TI[i], TR[i], PH[i], b) == FUR_OK);
            EXPECT(memcmp(a, b, sizeof a) == 0);
            EXPECT(fur_sample_far_at(&lut, own, TR[i], 0.3f, 0.6f, 0.2f, &sa) == FUR_OK);
            EXPECT(fur_sample_far(&lut, TR[i], 0.3f, 0.6f, 0.2f, &sb) == FUR_OK);
            EXPECT(memcmp(&sa, &sb, sizeof sa) == 0);
            pa = fur_pdf_far_at(&lut, own, TI[i], TR[i], PH[i]);
            pb = fur_pdf_far(&lut, TI[i], TR[i], PH[i]);
            EXPECT(bits(pa) == bits(pb));
        }
        EXPECT(fur_eval_far_dirs_at(&lut, own, wi, wr, t, a) == FUR_OK);
        EXPECT(fur_eval_far_dirs(&lut, wi, wr, t, b) == FUR_OK);
        EXPECT(memcmp(a, b, 3 * sizeof(float)) == 0);
    }
    /* N_COLOURS random colours, each with one of the fixed directions. */
    {
        float sigma[3 * N_COLOURS], bt[N_COLOURS], br[N_COLOURS], bp[N_COLOURS], out[3 * N_COLOURS];
        for (k = 0; k < 3 * N_COLOURS; k++) sigma[k] = colour_channel();
        for (k = 0; k < N_COLOURS; k++) {
            const float *c = sigma + 3 * k;
            float p = -1.0f;
            i = (size_t)k % N_DIRS;
            printf("colour %d %08x %08x %08x\n", k, bits(c[0]), bits(c[1]), bits(c[2]));
            EXPECT(fur_eval_far_at(&lut, c, TI[i], TR[i], PH[i], rgb) == FUR_OK);
            printf("evalat %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
            EXPECT(fur_eval_far_families_at(&lut, c, TI[i], TR[i], PH[i], fam) == FUR_OK);
            printf("familiesat");
            for (k2 = 0; k2 < 12; k2++) printf(" %08x", bits(fam[k2]));
            printf("\n");
            printf("pdfat %08x\n", bits(fur_pdf_far_at(&lut, c, TI[i], TR[i], PH[i])));
            EXPECT(fur_eval_far_dirs_at(&lut, c, wi, wr, t, rgb) == FUR_OK);
            printf("dirsat %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));
            EXPECT(fur_sample_far_at(&lut, c, TR[i], 0.1f + 0.03f * (float)k, 0.8f, 0.37f, &s) == FUR_OK);
            print_sample("sampleat", &s);
            printf("\n");
            EXPECT(fur_sample_pdf_far_at(&lut, c, TR[i], 0.1f + 0.03f * (float)k, 0.8f, 0.37f, TI[i], PH[i],
                                         &s, &p) == FUR_OK);
            print_sample("samplepdfat", &s);
            printf(" %08x\n", bits(p));
            bt[k] = TI[i];
            br[k] = TR[i];
            bp[k] = PH[i];
        }
        EXPECT(fur_eval_far_batch_at(&lut, N_COLOURS, sigma, bt, br, bp, out) == FUR_OK);
        printf("batchat");
        for (k = 0; k < 3 * N_COLOURS; k++) printf(" %08x", bits(out[k]));
        printf("\n");
        EXPECT(fur_sigma_from_melanin(0.4f, 1.5f, rgb) == FUR_OK);
        printf("melanin %08x %08x %08x\n", bits(rgb[0]), bits(rgb[1]), bits(rgb[2]));

        /* Refused colours: NaN, negative, -inf; 0 written, FUR_ERR_COLOUR. */
        {
            const float bad[3][3] = {{NAN, 0.5f, 0.5f}, {0.5f, -1e-9f, 0.5f}, {0.5f, 0.5f, -INFINITY}};
            for (k = 0; k < 3; k++) {
                float p = -1.0f;
                rgb[0] = -1.0f;
                EXPECT(fur_eval_far_at(&lut, bad[k], 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_COLOUR && rgb[0] == 0.0f);
                fam[11] = -1.0f;
                EXPECT(fur_eval_far_families_at(&lut, bad[k], 0.1f, 0.2f, 0.3f, fam) == FUR_ERR_COLOUR &&
                       fam[11] == 0.0f);
                EXPECT(fur_eval_far_dirs_at(&lut, bad[k], wi, wr, t, rgb) == FUR_ERR_COLOUR);
                EXPECT(fur_pdf_far_at(&lut, bad[k], 0.1f, 0.2f, 0.3f) == 0.0f);
                EXPECT(fur_sample_far_at(&lut, bad[k], 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_COLOUR);
                EXPECT(fur_sample_pdf_far_at(&lut, bad[k], 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, &p) ==
                       FUR_ERR_COLOUR && p == -1.0f);
            }
            /* One refused colour in a batch: its entry 0, the others as before. */
            {
                float again[3 * N_COLOURS];
                sigma[3 * 5 + 2] = NAN;
                EXPECT(fur_eval_far_batch_at(&lut, N_COLOURS, sigma, bt, br, bp, again) == FUR_ERR_COLOUR);
                EXPECT(again[15] == 0.0f && again[16] == 0.0f && again[17] == 0.0f);
                EXPECT(memcmp(again, out, 15 * sizeof(float)) == 0);
                EXPECT(memcmp(again + 18, out + 18, (3 * N_COLOURS - 18) * sizeof(float)) == 0);
            }
            EXPECT(fur_sigma_from_melanin(NAN, 0.0f, rgb) == FUR_ERR_COLOUR);
            EXPECT(fur_sigma_from_melanin(0.0f, -1.0f, rgb) == FUR_ERR_COLOUR);
            EXPECT(strstr(fur_status_str(FUR_ERR_COLOUR), "colour") != NULL);
        }
    }

    /* NULL and zero-length arguments for every function. */
    EXPECT(fur_lut_open(NULL, len, &lut) == FUR_ERR_NULL);
    EXPECT(fur_lut_open(bytes, len, NULL) == FUR_ERR_NULL);
    EXPECT(fur_lut_open(bytes, 0, &never) == FUR_ERR_LENGTH);
    EXPECT(fur_lut_open(bytes, len, &lut) == FUR_OK);
    EXPECT(fur_eval_far(NULL, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_far(&lut, 0.1f, 0.2f, 0.3f, NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_families(NULL, 0.1f, 0.2f, 0.3f, fam) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_families(&lut, 0.1f, 0.2f, 0.3f, NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_dirs(NULL, wi, wr, t, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_dirs(&lut, NULL, wr, t, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_dirs(&lut, wi, NULL, t, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_dirs(&lut, wi, wr, NULL, rgb) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_dirs(&lut, wi, wr, t, NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(NULL, 1, TI, TR, PH, batch) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(&lut, 0, NULL, NULL, NULL, NULL) == FUR_OK);
    EXPECT(fur_eval_far_batch(&lut, 1, NULL, TR, PH, batch) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(&lut, 1, TI, NULL, PH, batch) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(&lut, 1, TI, TR, NULL, batch) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(&lut, 1, TI, TR, PH, NULL) == FUR_ERR_NULL);
    EXPECT(fur_eval_far_batch(&lut, (size_t)-1, TI, TR, PH, batch) == FUR_ERR_LENGTH);
    EXPECT(fur_sample_far(NULL, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NULL);
    EXPECT(fur_sample_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, NULL) == FUR_ERR_NULL);
    EXPECT(fur_pdf_far(NULL, 0.1f, 0.2f, 0.3f) == 0.0f);
    {
        float p = -1.0f;
        EXPECT(fur_sample_pdf_far(NULL, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, &p) == FUR_ERR_NULL);
        EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, NULL, &p) == FUR_ERR_NULL);
        EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, NULL) == FUR_ERR_NULL);
        EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, (float *)misaligned) ==
               FUR_ERR_ALIGNMENT);
        /* Bad angles: refused, nothing written. */
        EXPECT(fur_sample_pdf_far(&lut, 1.7f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, &p) == FUR_ERR_ANGLE);
        EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 2.0f, 0.3f, &s, &p) == FUR_ERR_ANGLE);
        EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, NAN, &s, &p) == FUR_ERR_ANGLE);
        EXPECT(p == -1.0f);
    }
    EXPECT(fur_lut_close(NULL) == FUR_ERR_NULL);
    {
        /* The colour entry points: NULL for each pointer. */
        const float c[3] = {0.5f, 1.0f, 2.0f};
        float p = -1.0f;
        EXPECT(fur_eval_far_at(NULL, c, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_at(&lut, NULL, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_at(&lut, c, 0.1f, 0.2f, 0.3f, NULL) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_families_at(&lut, NULL, 0.1f, 0.2f, 0.3f, fam) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_families_at(&lut, c, 0.1f, 0.2f, 0.3f, NULL) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_dirs_at(&lut, NULL, wi, wr, t, rgb) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_dirs_at(&lut, c, wi, NULL, t, rgb) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_batch_at(&lut, 1, NULL, TI, TR, PH, batch) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_batch_at(&lut, 1, c, TI, TR, NULL, batch) == FUR_ERR_NULL);
        EXPECT(fur_eval_far_batch_at(&lut, 0, NULL, NULL, NULL, NULL, NULL) == FUR_OK);
        EXPECT(fur_eval_far_batch_at(&lut, (size_t)-1, c, TI, TR, PH, batch) == FUR_ERR_LENGTH);
        EXPECT(fur_sample_far_at(&lut, NULL, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NULL);
        EXPECT(fur_sample_far_at(&lut, c, 0.1f, 0.5f, 0.5f, 0.5f, NULL) == FUR_ERR_NULL);
        EXPECT(fur_sample_pdf_far_at(&lut, NULL, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &s, &p) == FUR_ERR_NULL);
        EXPECT(fur_pdf_far_at(&lut, NULL, 0.1f, 0.2f, 0.3f) == 0.0f);
        EXPECT(fur_pdf_far_at(NULL, c, 0.1f, 0.2f, 0.3f) == 0.0f);
        EXPECT(fur_lut_sigma_ca(NULL, rgb) == FUR_ERR_NULL);
        EXPECT(fur_lut_sigma_ca(&lut, NULL) == FUR_ERR_NULL);
        EXPECT(fur_sigma_from_melanin(0.4f, 1.5f, NULL) == FUR_ERR_NULL);
        /* Misaligned colour; the output over the colour, the fur_lut or the LUT bytes. */
        EXPECT(fur_eval_far_at(&lut, misaligned, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_ALIGNMENT);
        EXPECT(fur_eval_far_batch_at(&lut, 1, misaligned, TI, TR, PH, batch) == FUR_ERR_ALIGNMENT);
        {
            float ov[6] = {0.5f, 1.0f, 2.0f, 0.5f, 1.0f, 2.0f};
            EXPECT(fur_eval_far_at(&lut, ov, 0.1f, 0.2f, 0.3f, (float *)opaque(ov + 2)) == FUR_ERR_OVERLAP);
            EXPECT(fur_eval_far_dirs_at(&lut, ov, wi, wr, t, (float *)opaque(ov + 1)) == FUR_ERR_OVERLAP);
            EXPECT(fur_eval_far_batch_at(&lut, 1, ov, TI, TR, PH, (float *)opaque(ov + 2)) == FUR_ERR_OVERLAP);
            EXPECT(fur_sample_far_at(&lut, ov, 0.1f, 0.5f, 0.5f, 0.5f, (fur_sample *)opaque(ov)) ==
                   FUR_ERR_OVERLAP);
            EXPECT(ov[2] == 2.0f && ov[3] == 0.5f);
            EXPECT(fur_eval_far_at(&lut, c, 0.1f, 0.2f, 0.3f, (float *)(void *)(bytes + 32)) ==
                   FUR_ERR_OVERLAP);
            EXPECT(fur_lut_sigma_ca(&lut, (float *)(void *)&lut._opaque[3]) == FUR_ERR_OVERLAP);
        }
    }

    /* Misaligned pointers. */
    EXPECT(fur_eval_far(&lut, 0.1f, 0.2f, 0.3f, misaligned) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_eval_far_dirs(&lut, misaligned, wr, t, rgb) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_eval_far_batch(&lut, 1, misaligned, TR, PH, batch) == FUR_ERR_ALIGNMENT);
    EXPECT(fur_eval_far(( const fur_lut *)((const char *)&lut + 4), 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_ALIGNMENT);

    /* Bad angles and directions. */
    EXPECT(fur_eval_far(&lut, 2.0f, 0.2f, 0.3f, rgb) == FUR_ERR_ANGLE && rgb[0] == 0.0f);
    EXPECT(fur_sample_far(&lut, 1.7f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_ANGLE);
    EXPECT(fur_pdf_far(&lut, 0.1f, 0.2f, INFINITY) == 0.0f);
    {
        const float zero[3] = {0.0f, 0.0f, 0.0f};
        EXPECT(fur_eval_far_dirs(&lut, zero, wr, t, rgb) == FUR_ERR_DIRECTION);
    }

    /* Overlapping buffers: every output against the inputs, the fur_lut and the LUT bytes.
     * Refused before anything is written; adjacent buffers are fine. */
    {
        float ov[4 * N_DIRS + 4], v[4] = {0.3f, 0.8f, 0.2f, 0.0f};
        const unsigned char saved = bytes[40];
        memcpy(ov, TI, sizeof TI);
        EXPECT(fur_eval_far_batch(&lut, N_DIRS, ov, TR, PH, ov + 1) == FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far_batch(&lut, N_DIRS, TR, PH, ov, ov + N_DIRS - 1) == FUR_ERR_OVERLAP);
        EXPECT(memcmp(ov, TI, sizeof TI) == 0);
        EXPECT(fur_eval_far_batch(&lut, N_DIRS, ov, TR, PH, ov + N_DIRS) == FUR_OK);
        EXPECT(memcmp(ov + N_DIRS, batch, sizeof batch) == 0);
        EXPECT(fur_eval_far_batch(&lut, 1, TI, TR, PH, (float *)opaque(&lut)) == FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far_batch(&lut, 1, TI, TR, PH, (float *)(void *)(bytes + 64)) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far(&lut, 0.1f, 0.2f, 0.3f, (float *)(void *)&lut._opaque[100]) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far(&lut, 0.1f, 0.2f, 0.3f, (float *)(void *)(bytes + 32)) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far_families(&lut, 0.1f, 0.2f, 0.3f, (float *)(void *)(bytes + 48)) ==
               FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far_dirs(&lut, v, wr, t, v + 1) == FUR_ERR_OVERLAP);
        EXPECT(fur_eval_far_dirs(&lut, wi, wr, v, v + 2) == FUR_ERR_OVERLAP);
        EXPECT(fur_sample_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, (fur_sample *)(void *)(bytes + 16)) ==
               FUR_ERR_OVERLAP);
        {
            /* The two outputs against the LUT bytes, the fur_lut and each other. */
            fur_sample so;
            float p = -1.0f;
            EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f,
                                      (fur_sample *)(void *)(bytes + 16), &p) == FUR_ERR_OVERLAP);
            EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &so,
                                      (float *)(void *)(bytes + 36)) == FUR_ERR_OVERLAP);
            EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &so,
                                      (float *)(void *)&lut._opaque[7]) == FUR_ERR_OVERLAP);
            EXPECT(fur_sample_pdf_far(&lut, 0.1f, 0.5f, 0.5f, 0.5f, 0.2f, 0.3f, &so, &so.pdf) ==
                   FUR_ERR_OVERLAP);
            EXPECT(p == -1.0f);
        }
        EXPECT(fur_lut_open(bytes, len, (fur_lut *)(void *)(bytes + 8)) == FUR_ERR_OVERLAP);
        EXPECT(bytes[40] == saved);
        /* Nothing was written into the bytes or the fur_lut: both still open and validate. */
        EXPECT(fur_eval_far(&lut, TI[0], TR[0], PH[0], rgb) == FUR_OK);
        EXPECT(fur_lut_open(bytes, len, &never) == FUR_OK);
        EXPECT(fur_lut_close(&never) == FUR_OK);
    }

    /* Never opened: zeroed with memset, initialised with FUR_LUT_INIT, filled with 0xa5. */
    memset(&never, 0, sizeof never);
    EXPECT(fur_eval_far(&never, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);
    {
        fur_lut init = FUR_LUT_INIT;
        EXPECT(fur_eval_far(&init, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_eval_far_batch(&init, 1, TI, TR, PH, batch) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_sample_far(&init, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_pdf_far(&init, 0.1f, 0.2f, 0.3f) == 0.0f);
        {
            const float c[3] = {0.5f, 1.0f, 2.0f};
            EXPECT(fur_eval_far_at(&init, c, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);
            EXPECT(fur_eval_far_batch_at(&init, 1, c, TI, TR, PH, batch) == FUR_ERR_NOT_OPEN);
            EXPECT(fur_sample_far_at(&init, c, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NOT_OPEN);
            EXPECT(fur_pdf_far_at(&init, c, 0.1f, 0.2f, 0.3f) == 0.0f);
            EXPECT(fur_lut_sigma_ca(&init, rgb) == FUR_ERR_NOT_OPEN);
        }
    }
    memset(&never, 0xa5, sizeof never);
    EXPECT(fur_eval_far(&never, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_sample_far(&never, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NOT_OPEN);
    EXPECT(fur_pdf_far(&never, 0.1f, 0.2f, 0.3f) == 0.0f);

    /* Another build's fur_lut: word 1 holds the build tag (a hash of the library version,
     * compiler, target and stored layout); another build writes another one. */
    memcpy(&foreign, &lut, sizeof lut);
    EXPECT(fur_eval_far(&foreign, 0.1f, 0.2f, 0.3f, rgb) == FUR_OK);
    foreign._opaque[1] ^= 1u;
    EXPECT(fur_eval_far(&foreign, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_OTHER_BUILD);
    EXPECT(fur_eval_far_batch(&foreign, 1, TI, TR, PH, batch) == FUR_ERR_OTHER_BUILD);
    EXPECT(fur_sample_far(&foreign, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_OTHER_BUILD);
    EXPECT(fur_pdf_far(&foreign, 0.1f, 0.2f, 0.3f) == 0.0f);
    {
        const float c[3] = {0.5f, 1.0f, 2.0f};
        EXPECT(fur_eval_far_at(&foreign, c, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_OTHER_BUILD);
        EXPECT(fur_eval_far_batch_at(&foreign, 1, c, TI, TR, PH, batch) == FUR_ERR_OTHER_BUILD);
    }
    EXPECT(fur_lut_close(&foreign) == FUR_OK);
    {
        const fur_lut zero = FUR_LUT_INIT;
        EXPECT(memcmp(&foreign, &zero, sizeof zero) == 0); /* close zeroes the storage */
    }

    /* Close, then free the bytes: the closed fur_lut is refused and reads nothing (Valgrind
     * sees any read of the freed copy). Then the two-function use-after-free sequence. */
    {
        unsigned char *heap = (unsigned char *)malloc(small_len);
        fur_lut h = FUR_LUT_INIT;
        if (!heap) return 2;
        memcpy(heap, small, small_len);
        EXPECT(fur_lut_open(heap, small_len, &h) == FUR_OK);
        EXPECT(fur_eval_far(&h, 0.1f, 0.2f, 0.3f, rgb) == FUR_OK);
        EXPECT(fur_lut_close(&h) == FUR_OK);
        free(heap);
        EXPECT(fur_eval_far(&h, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_eval_far_batch(&h, 1, TI, TR, PH, batch) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_sample_far(&h, 0.1f, 0.5f, 0.5f, 0.5f, &s) == FUR_ERR_NOT_OPEN);
        EXPECT(fur_pdf_far(&h, 0.1f, 0.2f, 0.3f) == 0.0f);

        heap = (unsigned char *)malloc(small_len);
        if (!heap) return 2;
        memcpy(heap, small, small_len);
        EXPECT(open_then_close(heap, small_len) == FUR_OK);
        free(heap);
        EXPECT(eval_fresh(rgb) == FUR_ERR_NOT_OPEN);
    }
    EXPECT(fur_lut_close(&lut) == FUR_OK);
    EXPECT(fur_eval_far(&lut, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN);

    /* 100 000 mutated blobs: one bit flipped, truncated, or with bytes appended. */
    copy = (unsigned char *)malloc(small_len + 64);
    if (!copy) return 2;
    EXPECT(fur_lut_open(small, small_len, &lut) == FUR_OK);
    for (k = 0; k < 100000; k++) {
        size_t n = small_len;
        fur_status st;
        memcpy(copy, small, small_len);
        switch (k % 3) {
        case 0:
            copy[rng() % small_len] ^= (unsigned char)(1u << (rng() % 8));
            break;
        case 1:
            n = rng() % small_len;
            break;
        default:
            n = small_len + 1 + rng() % 63;
            for (i = small_len; i < n; i++) copy[i] = (unsigned char)rng();
            break;
        }
        st = fur_lut_open(copy, n, &never);
        if (st != FUR_OK && fur_eval_far(&never, 0.1f, 0.2f, 0.3f, rgb) == FUR_ERR_NOT_OPEN &&
            strlen(fur_status_str((int32_t)st)) > 0)
            refused++;
    }
    EXPECT(refused == 100000);
    printf("mutated refused %d of 100000\n", refused);
    EXPECT(strcmp(fur_status_str(12345), "unknown status") == 0);
    EXPECT(fur_lut_close(&lut) == FUR_OK); /* before its bytes are freed */
    free(copy);
    free(bytes);
    free(small);
    if (failures) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    printf("bad-input ok\n");
    return 0;
}
