struct FurFamilies {
    float3 r;
    int _pad1_0;
    float3 tt;
    int _pad2_0;
    float3 trt;
    int _pad3_0;
    float3 scattered;
    int _pad4_0;
    float3 total;
    int _end_pad_0;
};

struct FurAxis {
    float inv_step;
    float offset;
    float last;
    uint nodes;
};

struct FurLoc {
    uint i;
    float w;
};

struct FurColour {
    uint3 plane;
    int _pad1_0;
    float3 w0_;
    int _pad2_0;
    float3 w1_;
    int _pad3_0;
    float3 w2_;
    int _end_pad_0;
};

struct FurLookups {
    float m[3];
    float ms[2];
    float n[12];
    float n0_[4];
    float front;
    float inv_cos2_;
};

struct FurDensity {
    uint prefix_at;
    uint entries;
    uint nodes;
    uint rows;
    float step_;
    uint block;
    uint table;
    uint channel;
};

struct FurDirAngles {
    float theta_i;
    float theta_r;
    float phi;
    bool ok;
};

struct FurSample {
    float theta_i;
    float phi;
    float pdf;
    int _pad3_0;
    float3 weight;
    uint family;
    bool ok;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct FurRows {
    FurDensity d;
    uint r0_;
    uint r1_;
    float w;
    float origin;
    uint weighting;
};

struct FurRange {
    float lo;
    float hi;
    float start;
    float raw;
    float4 s;
};

struct FurMAt {
    float3 cdf;
    int _pad1_0;
    float3 value;
    int _end_pad_0;
};

struct FurParts {
    float a[5];
    int _pad1_0;
    int _pad1_1;
    int _pad1_2;
    FurRange ranges[5];
};

struct FurDualColour {
    uint3 node;
    int _pad1_0;
    float3 w;
    int _end_pad_0;
};

static const float FUR_PI = 3.1415927;
static const float FUR_HALF_PI = 1.5707964;
static const float FUR_TAU = 6.2831855;
static const float FUR_MIN_COS2_ = 0.0001;
static const float FUR_POLE_SLIVER = 0.010000167;
static const uint FUR_HEADER_HALVES = 84u;
static const uint FUR_N_ABS_WORD = 9u;
static const uint FUR_SCALE_WORD = 10u;
static const uint FUR_ABS_SCALE_WORD = 39u;
static const float FUR_SIGMA_CA_MAX = 1000.0;
static const float FUR_ROOT_RATE = 8.325476;
static const float FUR_ROOT_SHARE = 0.4;
static const float FUR_LOG2_E = 1.442695;
static const uint FUR_CLOSURE_WORD = 27u;
static const uint FUR_DUAL_HEADER_WORDS = 20u;
static const uint FUR_DUAL_ABS_NODES = 16u;
static const uint FUR_DUAL_NODE_HALVES = 9152u;
static const float FUR_DUAL_KNEE = 3.0;
static const float FUR_DUAL_SIGMA_MAX = 1000.0;
static const uint FUR_DUAL_FIELDS = 15u;
static const uint FUR_DUAL_LOG2_DECAY = 0u;
static const uint FUR_DUAL_BETA_F = 1u;
static const uint FUR_DUAL_BACK = 2u;
static const uint FUR_DUAL_FRONT = 3u;
static const uint FUR_DUAL_DELTA_B = 4u;
static const uint FUR_DUAL_SIGMA_B0_ = 5u;
static const uint FUR_DUAL_A_F2_ = 6u;
static const uint FUR_DUAL_MEAN = 7u;
static const uint FUR_DUAL_SD = 11u;
static const uint FUR_DUAL_THETA_NODES = 64u;
static const uint FUR_DUAL_PHI_NODES = 32u;
static const uint FUR_DUAL_NG_START = 960u;
static const float FUR_DUAL_THETA_SCALE = 20.371832;
static const float FUR_DUAL_PHI_SCALE = 9.867606;
static const float FUR_DUAL_MAX_FIBERS = 1000000.0;
static const float FUR_DUAL_MAX_DENSITY = 4.0;
static const float FUR_DUAL_MIN_VARIANCE = 3e-6;
static const float FUR_DUAL_LINE_SAMPLE_OFFSET = 1.0;
static const float FUR_DUAL_MIN_MASS = 0.05;
static const float FUR_DUAL_TINY = 1e-6;
static const float FUR_LN2_ = 0.6931472;
static const float FUR_LN2_HI = 0.6933594;
static const float FUR_LN2_LO = -0.00021219444;
static const float FUR_INV_SQRT_TAU = 0.3989423;
static const float FUR_FRAC_1_SQRT_2_ = 0.70710677;
static const float FUR_ERF_A1_ = 0.07052308;
static const float FUR_ERF_A2_ = 0.04228201;
static const float FUR_ERF_A3_ = 0.009270527;
static const float FUR_ERF_A4_ = 0.0001520143;
static const float FUR_ERF_A5_ = 0.0002765672;
static const float FUR_ERF_A6_ = 4.30638e-5;
static const float FUR_DUAL_DIFFUSIVITY = 2.0;
static const uint FUR_COAT_NODES = 24u;
static const float FUR_COAT_AXIS_END = 0.9995004;

ByteAddressBuffer fur_lut : register(t0);
ByteAddressBuffer fur_dual : register(t3);
static FurDualColour fur_dual_at = (FurDualColour)0;
ByteAddressBuffer fur_queries : register(t1);
RWByteAddressBuffer fur_results : register(u2);

FurAxis ConstructFurAxis(float arg0, float arg1, float arg2, uint arg3) {
    FurAxis ret = (FurAxis)0;
    ret.inv_step = arg0;
    ret.offset = arg1;
    ret.last = arg2;
    ret.nodes = arg3;
    return ret;
}

FurAxis fur_axis(bool centred, float inv_span, uint nodes)
{
    float last_1 = float((nodes - 1u));
    const FurAxis furaxis = ConstructFurAxis((last_1 * inv_span), (centred ? (0.5 * last_1) : 0.0), last_1, nodes);
    return furaxis;
}

FurLoc ConstructFurLoc(uint arg0, float arg1) {
    FurLoc ret = (FurLoc)0;
    ret.i = arg0;
    ret.w = arg1;
    return ret;
}

int naga_f2i32(float value) {
    return int(clamp(value, -2147483600.0, 2147483500.0));
}

FurLoc fur_locate(FurAxis a, float x)
{
    float u_7 = min(max(((x * a.inv_step) + a.offset), 0.0), a.last);
    int i_1 = min(naga_f2i32(u_7), asint(asuint(int(a.nodes)) - asuint(int(2))));
    const FurLoc furloc = ConstructFurLoc(uint(i_1), (u_7 - float(i_1)));
    return furloc;
}

uint fur_word(uint k)
{
    uint _e3 = asuint(fur_lut.Load(k*4));
    return _e3;
}

float fur_half(uint h)
{
    uint word = asuint(fur_lut.Load((h >> 1u)*4));
    uint bits = (((h & 1u) == 1u) ? (word >> 16u) : (word & 65535u));
    return asfloat((bits << 13u));
}

float fur_unbias(uint t)
{
    const uint _e3 = fur_word((FUR_SCALE_WORD + t));
    return (asfloat(_e3) * asfloat(2004877312u));
}

uint fur_n_plane_halves()
{
    const uint _e2 = fur_word(6u);
    const uint _e5 = fur_word(5u);
    return ((4u * _e2) * _e5);
}

bool3 fur_is_nan3_(float3 x_1)
{
    return ((asuint(x_1) & (2147483647u).xxx) > (2139095040u).xxx);
}

int3 naga_neg(int3 val) {
    return asint(-asuint(val));
}

int3 naga_f2i32(float3 value) {
    return int3(clamp(value, -2147483600.0, 2147483500.0));
}

float3 fur_pow2_neg(float3 y_in)
{
    const bool3 _e9 = fur_is_nan3_(y_in);
    float3 y_3 = (_e9 ? (0.0).xxx : min(max(y_in, (0.0).xxx), (125.0).xxx));
    float3 k_17 = round(y_3);
    float3 f_6 = (k_17 - y_3);
    float3 f2_ = (f_6 * f_6);
    float3 f4_ = (f2_ * f2_);
    float3 p01_ = ((1.5252734e-5 * f_6) + (0.0001540353).xxx);
    float3 p23_ = ((0.0013333558 * f_6) + (0.009618129).xxx);
    float3 p45_ = ((0.05550411 * f_6) + (0.2402265).xxx);
    float3 p67_ = ((0.6931472 * f_6) + (1.0).xxx);
    float3 p_4 = ((((p01_ * f2_) + p23_) * f4_) + ((p45_ * f2_) + p67_));
    return ldexp(p_4, naga_neg(naga_f2i32(k_17)));
}

FurColour ConstructFurColour(uint3 arg0, float3 arg1, float3 arg2, float3 arg3) {
    FurColour ret = (FurColour)0;
    ret.plane = arg0;
    ret.w0_ = arg1;
    ret.w1_ = arg2;
    ret.w2_ = arg3;
    return ret;
}

uint3 naga_f2u32(float3 value) {
    return uint3(clamp(value, 0.0, 4294967000.0));
}

FurColour fur_locate_colour(float3 sigma_ca)
{
    const uint _e2 = fur_word(FUR_N_ABS_WORD);
    float last_2 = float((_e2 - 1u));
    const uint _e7 = fur_word(FUR_ABS_SCALE_WORD);
    float scale = asfloat(_e7);
    const bool3 _e17 = fur_is_nan3_(sigma_ca);
    float3 s_1 = (_e17 ? (0.0).xxx : min(max(sigma_ca, (0.0).xxx), (1000.0).xxx));
    const float3 _e23 = fur_pow2_neg(sqrt((s_1 * FUR_ROOT_RATE)));
    const float3 _e30 = fur_pow2_neg(((s_1 / (scale).xxx) * FUR_LOG2_E));
    float3 e = ((FUR_ROOT_SHARE * _e23) + (0.6 * _e30));
    float3 x_16 = min(((1.0).xxx - e), (1.0).xxx);
    float3 u_8 = clamp((x_16 * last_2), (0.0).xxx, (last_2).xxx);
    uint3 k_18 = min(naga_f2u32(u_8), ((_e2 - 3u)).xxx);
    float3 t_11 = (u_8 - float3(k_18));
    float3 w0_ = ((0.5 * (t_11 - (1.0).xxx)) * (t_11 - (2.0).xxx));
    float3 w1_ = (t_11 * ((2.0).xxx - t_11));
    float3 w2_ = ((0.5 * t_11) * (t_11 - (1.0).xxx));
    const uint _e71 = fur_word(6u);
    const uint _e73 = fur_word(5u);
    const FurColour furcolour = ConstructFurColour((k_18 * (_e71 * _e73)), w0_, w1_, w2_);
    return furcolour;
}

float fur_cos_within_half_pi(float x_2)
{
    float acc = -2.755732e-7;
    float acc_1 = 2.7557319e-6;

    float a_7 = abs(x_2);
    if ((a_7 <= 0.7853982)) {
        float y_4 = (a_7 * a_7);
        float _e7 = acc;
        acc = ((_e7 * y_4) + 2.4801588e-5);
        float _e11 = acc;
        acc = ((_e11 * y_4) - 0.0013888889);
        float _e15 = acc;
        acc = ((_e15 * y_4) + 0.041666668);
        float _e19 = acc;
        acc = ((_e19 * y_4) - 0.5);
        float _e23 = acc;
        return ((_e23 * y_4) + 1.0);
    }
    float r_13 = ((1.5707964 - a_7) + ((a_7 > 4.0) ? 0.0 : -4.371139e-8));
    float y_5 = (r_13 * r_13);
    float _e38 = acc_1;
    acc_1 = ((_e38 * y_5) - 0.0001984127);
    float _e42 = acc_1;
    acc_1 = ((_e42 * y_5) + 0.008333334);
    float _e46 = acc_1;
    acc_1 = ((_e46 * y_5) - 0.16666667);
    float _e50 = acc_1;
    return (((_e50 * y_5) * r_13) + r_13);
}

float fur_wrap_angle(float x_3)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;
    float y = (float)0;
    bool local_3 = (bool)0;

    if ((x_3 > -3.1415927)) {
        local = (x_3 <= FUR_PI);
    } else {
        local = false;
    }
    bool _e8 = local;
    if (_e8) {
        return x_3;
    }
    if ((x_3 > FUR_PI)) {
        local_1 = (x_3 <= 9.424778);
    } else {
        local_1 = false;
    }
    bool _e16 = local_1;
    if (_e16) {
        return (x_3 - FUR_TAU);
    }
    if ((x_3 <= -3.1415927)) {
        local_2 = (x_3 > -9.424778);
    } else {
        local_2 = false;
    }
    bool _e26 = local_2;
    if (_e26) {
        return (x_3 + FUR_TAU);
    }
    y = (x_3 - (FUR_TAU * floor(((x_3 + FUR_PI) / FUR_TAU))));
    float _e38 = y;
    if ((_e38 <= -3.1415927)) {
        float _e41 = y;
        y = (_e41 + FUR_TAU);
    }
    float _e44 = y;
    if ((_e44 > FUR_PI)) {
        float _e47 = y;
        y = (_e47 - FUR_TAU);
    }
    float _e50 = y;
    if ((_e50 > -3.1415927)) {
        float _e55 = y;
        local_3 = (_e55 <= FUR_PI);
    } else {
        local_3 = false;
    }
    bool _e59 = local_3;
    if (_e59) {
        float _e60 = y;
        return _e60;
    }
    return 0.0;
}

FurFamilies ConstructFurFamilies(float3 arg0, float3 arg1, float3 arg2, float3 arg3, float3 arg4) {
    FurFamilies ret = (FurFamilies)0;
    ret.r = arg0;
    ret.tt = arg1;
    ret.trt = arg2;
    ret.scattered = arg3;
    ret.total = arg4;
    return ret;
}

FurFamilies fur_zero()
{
    float3 z = (0.0).xxx;
    const FurFamilies furfamilies = ConstructFurFamilies(z, z, z, z, z);
    return furfamilies;
}

bool fur_finite(float x_4)
{
    return ((asuint(x_4) & 2139095040u) != 2139095040u);
}

bool fur_valid(float theta_i, float theta_r, float phi)
{
    bool local_4 = (bool)0;
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;
    bool local_7 = (bool)0;

    const bool _e3 = fur_finite(theta_i);
    if (_e3) {
        const bool _e6 = fur_finite(theta_r);
        local_4 = _e6;
    } else {
        local_4 = false;
    }
    bool _e8 = local_4;
    if (_e8) {
        const bool _e11 = fur_finite(phi);
        local_5 = _e11;
    } else {
        local_5 = false;
    }
    bool _e13 = local_5;
    if (_e13) {
        local_6 = (abs(theta_i) <= FUR_HALF_PI);
    } else {
        local_6 = false;
    }
    bool _e20 = local_6;
    if (_e20) {
        local_7 = (abs(theta_r) <= FUR_HALF_PI);
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    return _e27;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint fur_entries(uint nodes_1, uint block)
{
    return (naga_div((((nodes_1 - 1u) + block) - 1u), block) + 1u);
}

FurDensity ConstructFurDensity(uint arg0, uint arg1, uint arg2, uint arg3, float arg4, uint arg5, uint arg6, uint arg7) {
    FurDensity ret = (FurDensity)0;
    ret.prefix_at = arg0;
    ret.entries = arg1;
    ret.nodes = arg2;
    ret.rows = arg3;
    ret.step_ = arg4;
    ret.block = arg5;
    ret.table = arg6;
    ret.channel = arg7;
    return ret;
}

FurDensity fur_density(uint d)
{
    uint at = (uint)0;

    const uint _e2 = fur_word(4u);
    const uint _e4 = fur_word(5u);
    const uint _e6 = fur_word(6u);
    const uint _e8 = fur_word(7u);
    const uint _e10 = fur_word(8u);
    const uint _e13 = fur_n_plane_halves();
    const uint _e15 = fur_word(FUR_N_ABS_WORD);
    uint values = (((3u * _e2) + (_e13 * _e15)) + ((2u * _e8) * _e10));
    at = (168u + (2u * values));
    const uint _e28 = fur_entries(_e2, 1u);
    const uint _e30 = fur_entries(_e6, 8u);
    const uint _e32 = fur_entries(_e8, 8u);
    if ((d < 3u)) {
        uint _e35 = at;
        const FurDensity furdensity = ConstructFurDensity((_e35 + ((4u * d) * _e28)), _e28, _e2, 1u, (6.2831855 / float((_e2 - 1u))), 1u, 0u, d);
        return furdensity;
    }
    uint _e49 = at;
    at = (_e49 + (12u * _e28));
    if ((d < 7u)) {
        uint f_7 = (d - 3u);
        uint _e57 = at;
        const FurDensity furdensity_1 = ConstructFurDensity((_e57 + (((4u * f_7) * _e4) * _e30)), _e30, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, f_7);
        return furdensity_1;
    }
    uint _e71 = at;
    at = (_e71 + ((16u * _e4) * _e30));
    if ((d < 9u)) {
        uint x_17 = (d - 7u);
        uint _e80 = at;
        const FurDensity furdensity_2 = ConstructFurDensity((_e80 + (((4u * x_17) * _e10) * _e32)), _e32, _e8, _e10, (FUR_PI / float((_e8 - 1u))), 8u, 2u, x_17);
        return furdensity_2;
    }
    uint _e94 = at;
    at = (_e94 + ((8u * _e10) * _e32));
    uint _e99 = at;
    const FurDensity furdensity_3 = ConstructFurDensity(_e99, _e30, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, 3u);
    return furdensity_3;
}

uint fur_norm_start()
{
    const FurDensity _e1 = fur_density(9u);
    return (_e1.prefix_at + ((4u * _e1.rows) * _e1.entries));
}

float fur_f32_at(uint byte)
{
    uint w_4 = (byte >> 2u);
    if (((byte & 3u) == 0u)) {
        uint _e9 = asuint(fur_lut.Load(w_4*4));
        return asfloat(_e9);
    }
    uint _e13 = asuint(fur_lut.Load(w_4*4));
    uint _e20 = asuint(fur_lut.Load((w_4 + 1u)*4));
    return asfloat(((_e13 >> 16u) | (_e20 << 16u)));
}

float3 fur_sphere_norms(float theta_r_1)
{
    float3 out_ = (0.0).xxx;
    uint g = 0u;

    const uint _e2 = fur_word(FUR_CLOSURE_WORD);
    if ((_e2 != 1u)) {
        return (1.0).xxx;
    }
    const uint _e10 = fur_word(4u);
    const FurAxis _e11 = fur_axis(true, 0.31830987, _e10);
    const FurLoc _e12 = fur_locate(_e11, theta_r_1);
    const uint _e13 = fur_norm_start();
    uint at_1 = (_e13 + (12u * _e12.i));
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e44 = g;
            g = (_e44 + 1u);
        }
        loop_init = false;
        uint _e23 = g;
        if ((_e23 < 3u)) {
        } else {
            break;
        }
        {
            uint _e27 = g;
            const float _e30 = fur_f32_at((at_1 + (4u * _e27)));
            uint _e31 = g;
            uint _e36 = g;
            const float _e39 = fur_f32_at(((at_1 + 12u) + (4u * _e36)));
            out_[min(uint(_e31), 2u)] = (_e30 + ((_e39 - _e30) * _e12.w));
        }
    }
    float3 _e47 = out_;
    return _e47;
}

typedef float ret_Constructarray6_float_[6];
ret_Constructarray6_float_ Constructarray6_float_(float arg0, float arg1, float arg2, float arg3, float arg4, float arg5) {
    float ret[6] = { arg0, arg1, arg2, arg3, arg4, arg5 };
    return ret;
}

typedef uint ret_Constructarray6_uint_[6];
ret_Constructarray6_uint_ Constructarray6_uint_(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4, uint arg5) {
    uint ret[6] = { arg0, arg1, arg2, arg3, arg4, arg5 };
    return ret;
}

FurLookups ConstructFurLookups(float arg0[3], float arg1[2], float arg2[12], float arg3[4], float arg4, float arg5) {
    FurLookups ret = (FurLookups)0;
    ret.m = arg0;
    ret.ms = arg1;
    ret.n = arg2;
    ret.n0_ = arg3;
    ret.front = arg4;
    ret.inv_cos2_ = arg5;
    return ret;
}

FurLookups fur_lookups(float theta_i_1, float theta_r_2, float phi_in, float3 sigma_ca_1)
{
    float m[3] = (float[3])0;
    uint ch = 0u;
    uint ch_1 = 0u;
    float ms[2] = (float[2])0;
    uint ch_2 = 0u;
    float n[12] = (float[12])0;
    uint c = 0u;
    uint f = (uint)0;
    float left = (float)0;
    float right = (float)0;
    uint i = (uint)0;
    float nl[4] = (float[4])0;
    uint f_1 = 0u;

    const float _e4 = fur_wrap_angle(phi_in);
    const uint _e6 = fur_word(4u);
    const uint _e8 = fur_word(5u);
    const uint _e10 = fur_word(6u);
    const uint _e12 = fur_word(7u);
    const uint _e14 = fur_word(8u);
    uint n0_ = (FUR_HEADER_HALVES + (3u * _e6));
    const uint _e19 = fur_n_plane_halves();
    const uint _e21 = fur_word(FUR_N_ABS_WORD);
    uint s0_ = (n0_ + (_e19 * _e21));
    float abs_phi = abs(_e4);
    const float _e25 = fur_cos_within_half_pi(theta_i_1);
    float inv_cos2_ = (1.0 / max((_e25 * _e25), FUR_MIN_COS2_));
    const FurAxis _e33 = fur_axis(true, 0.15915494, _e6);
    const FurLoc _e35 = fur_locate(_e33, (theta_i_1 + theta_r_2));
    const float _e37 = fur_unbias(0u);
    float wm0_ = ((1.0 - _e35.w) * _e37);
    float wm1_ = (_e35.w * _e37);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e71 = ch;
            ch = (_e71 + 1u);
        }
        loop_init_1 = false;
        uint _e47 = ch;
        if ((_e47 < 3u)) {
        } else {
            break;
        }
        {
            uint _e54 = ch;
            const float _e56 = fur_half(((FUR_HEADER_HALVES + (3u * _e35.i)) + _e54));
            uint _e63 = ch;
            const float _e65 = fur_half(((FUR_HEADER_HALVES + (3u * (_e35.i + 1u))) + _e63));
            uint _e66 = ch;
            m[min(uint(_e66), 2u)] = ((wm0_ * _e56) + (wm1_ * _e65));
        }
    }
    const float3 _e74 = fur_sphere_norms(theta_r_2);
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e88 = ch_1;
            ch_1 = (_e88 + 1u);
        }
        loop_init_2 = false;
        uint _e77 = ch_1;
        if ((_e77 < 3u)) {
        } else {
            break;
        }
        {
            uint _e80 = ch_1;
            uint _e82 = ch_1;
            float _e84 = m[min(uint(_e82), 2u)];
            uint _e85 = ch_1;
            m[min(uint(_e80), 2u)] = (_e84 * _e74[min(uint(_e85), 2u)]);
        }
    }
    const FurAxis _e93 = fur_axis(true, 0.31830987, _e14);
    const FurLoc _e94 = fur_locate(_e93, theta_r_2);
    const FurAxis _e97 = fur_axis(true, 0.31830987, _e12);
    const FurLoc _e98 = fur_locate(_e97, theta_i_1);
    const float _e100 = fur_unbias(2u);
    {
        float ky0_ = ((1.0 - _e94.w) * _e100);
        float ky1_ = (_e94.w * _e100);
        float w0_1 = (ky0_ * (1.0 - _e98.w));
        float w1_1 = (ky0_ * _e98.w);
        float w2_1 = (ky1_ * (1.0 - _e98.w));
        float w3_ = (ky1_ * _e98.w);
        uint i0_ = ((_e94.i * _e12) + _e98.i);
        uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
        bool loop_init_3 = true;
        while(true) {
            if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init_3) {
                uint _e168 = ch_2;
                ch_2 = (_e168 + 1u);
            }
            loop_init_3 = false;
            uint _e126 = ch_2;
            if ((_e126 < 2u)) {
            } else {
                break;
            }
            {
                uint _e132 = ch_2;
                const float _e134 = fur_half(((s0_ + (2u * i0_)) + _e132));
                uint _e140 = ch_2;
                const float _e142 = fur_half(((s0_ + (2u * (i0_ + 1u))) + _e140));
                uint _e147 = ch_2;
                const float _e149 = fur_half(((s0_ + (2u * (i0_ + _e12))) + _e147));
                uint _e156 = ch_2;
                const float _e158 = fur_half(((s0_ + (2u * ((i0_ + _e12) + 1u))) + _e156));
                uint _e159 = ch_2;
                ms[min(uint(_e159), 1u)] = ((((w0_1 * _e134) + (w1_1 * _e142)) + (w2_1 * _e149)) + (w3_ * _e158));
            }
        }
    }
    float front_w = min((abs_phi * 0.31830987), 1.0);
    const FurAxis _e177 = fur_axis(false, 0.63661975, _e8);
    const FurLoc _e179 = fur_locate(_e177, abs(theta_r_2));
    const FurAxis _e182 = fur_axis(false, 0.31830987, _e10);
    const FurLoc _e183 = fur_locate(_e182, abs_phi);
    const float _e185 = fur_unbias(1u);
    float ny0_ = ((1.0 - _e179.w) * _e185);
    float ny1_ = (_e179.w * _e185);
    float v0_8 = (ny0_ * (1.0 - _e183.w));
    float v1_8 = (ny0_ * _e183.w);
    float v2_ = (ny1_ * (1.0 - _e183.w));
    float v3_ = (ny1_ * _e183.w);
    uint j0_ = ((_e179.i * _e10) + _e183.i);
    const FurColour _e208 = fur_locate_colour(sigma_ca_1);
    const uint _e209 = fur_n_plane_halves();
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e342 = c;
            c = (_e342 + 1u);
        }
        loop_init_4 = false;
        uint _e213 = c;
        if ((_e213 < 3u)) {
        } else {
            break;
        }
        {
            uint _e217 = c;
            uint _e220 = c;
            uint _e223 = c;
            float3 tw = float3(_e208.w0_[min(uint(_e217), 2u)], _e208.w1_[min(uint(_e220), 2u)], _e208.w2_[min(uint(_e223), 2u)]);
            float l_8[6] = Constructarray6_float_((tw.x * v0_8), (tw.x * v2_), (tw.y * v0_8), (tw.y * v2_), (tw.z * v0_8), (tw.z * v2_));
            float r_14[6] = Constructarray6_float_((tw.x * v1_8), (tw.x * v3_), (tw.y * v1_8), (tw.y * v3_), (tw.z * v1_8), (tw.z * v3_));
            uint _e254 = c;
            uint h_3 = (n0_ + (4u * (_e208.plane[min(uint(_e254), 2u)] + j0_)));
            uint rows[6] = Constructarray6_uint_(h_3, (h_3 + (4u * _e10)), (h_3 + _e209), ((h_3 + _e209) + (4u * _e10)), (h_3 + (2u * _e209)), ((h_3 + (2u * _e209)) + (4u * _e10)));
            f = 0u;
            uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e339 = f;
                    f = (_e339 + 1u);
                }
                loop_init_5 = false;
                uint _e279 = f;
                if ((_e279 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e283 = f;
                    const float _e285 = fur_half((rows[0] + _e283));
                    left = (_e285 * l_8[0]);
                    uint _e292 = f;
                    const float _e294 = fur_half(((rows[0] + 4u) + _e292));
                    right = (_e294 * r_14[0]);
                    i = 1u;
                    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e325 = i;
                            i = (_e325 + 1u);
                        }
                        loop_init_6 = false;
                        uint _e300 = i;
                        if ((_e300 < 6u)) {
                        } else {
                            break;
                        }
                        {
                            float _e303 = left;
                            uint _e304 = i;
                            uint _e306 = f;
                            const float _e308 = fur_half((rows[min(uint(_e304), 5u)] + _e306));
                            uint _e309 = i;
                            left = (_e303 + (_e308 * l_8[min(uint(_e309), 5u)]));
                            float _e313 = right;
                            uint _e314 = i;
                            uint _e318 = f;
                            const float _e320 = fur_half(((rows[min(uint(_e314), 5u)] + 4u) + _e318));
                            uint _e321 = i;
                            right = (_e313 + (_e320 * r_14[min(uint(_e321), 5u)]));
                        }
                    }
                    uint _e329 = f;
                    uint _e331 = c;
                    float _e334 = left;
                    float _e335 = right;
                    n[min(uint(((3u * _e329) + _e331)), 11u)] = max((_e334 + _e335), 0.0);
                }
            }
        }
    }
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e390 = f_1;
            f_1 = (_e390 + 1u);
        }
        loop_init_7 = false;
        uint _e348 = f_1;
        if ((_e348 < 4u)) {
        } else {
            break;
        }
        {
            uint _e354 = f_1;
            const float _e356 = fur_half(((n0_ + (4u * j0_)) + _e354));
            uint _e362 = f_1;
            const float _e364 = fur_half(((n0_ + (4u * (j0_ + 1u))) + _e362));
            uint _e369 = f_1;
            const float _e371 = fur_half(((n0_ + (4u * (j0_ + _e10))) + _e369));
            uint _e378 = f_1;
            const float _e380 = fur_half(((n0_ + (4u * ((j0_ + _e10) + 1u))) + _e378));
            uint _e381 = f_1;
            nl[min(uint(_e381), 3u)] = ((((v0_8 * _e356) + (v1_8 * _e364)) + (v2_ * _e371)) + (v3_ * _e380));
        }
    }
    float _e393[3] = m;
    float _e394[2] = ms;
    float _e395[12] = n;
    float _e396[4] = nl;
    const FurLookups furlookups = ConstructFurLookups(_e393, _e394, _e395, _e396, front_w, inv_cos2_);
    return furlookups;
}

typedef float ret_Constructarray4_float_[4];
ret_Constructarray4_float_ Constructarray4_float_(float arg0, float arg1, float arg2, float arg3) {
    float ret[4] = { arg0, arg1, arg2, arg3 };
    return ret;
}

FurFamilies fur_assemble(FurLookups l)
{
    float3 f_2[4] = (float3[4])0;
    uint k_1 = 0u;

    float mss = (l.ms[0] + (l.front * (l.ms[1] - l.ms[0])));
    float lon[4] = Constructarray4_float_(l.m[0], l.m[1], l.m[2], mss);
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e51 = k_1;
            k_1 = (_e51 + 1u);
        }
        loop_init_8 = false;
        uint _e21 = k_1;
        if ((_e21 < 4u)) {
        } else {
            break;
        }
        {
            uint _e24 = k_1;
            float weight = (lon[min(uint(_e24), 3u)] * l.inv_cos2_);
            uint _e28 = k_1;
            uint _e32 = k_1;
            uint _e37 = k_1;
            uint _e44 = k_1;
            f_2[min(uint(_e28), 3u)] = (float3(l.n[min(uint((3u * _e32)), 11u)], l.n[min(uint(((3u * _e37) + 1u)), 11u)], l.n[min(uint(((3u * _e44) + 2u)), 11u)]) * weight);
        }
    }
    float3 _e55 = f_2[0];
    float3 _e57 = f_2[1];
    float3 _e59 = f_2[2];
    float3 _e61 = f_2[3];
    float3 _e63 = f_2[0];
    float3 _e65 = f_2[1];
    float3 _e68 = f_2[2];
    float3 _e71 = f_2[3];
    const FurFamilies furfamilies_1 = ConstructFurFamilies(_e55, _e57, _e59, _e61, (((_e63 + _e65) + _e68) + _e71));
    return furfamilies_1;
}

FurFamilies fur_eval_far(float theta_i_2, float theta_r_3, float phi_1, float3 sigma_ca_2)
{
    const bool _e4 = fur_valid(theta_i_2, theta_r_3, phi_1);
    if (!(_e4)) {
        const FurFamilies _e6 = fur_zero();
        const FurFamilies furfamilies_2 = _e6;
        return furfamilies_2;
    }
    const FurLookups _e7 = fur_lookups(theta_i_2, theta_r_3, phi_1, sigma_ca_2);
    const FurFamilies _e8 = fur_assemble(_e7);
    const FurFamilies furfamilies_3 = _e8;
    return furfamilies_3;
}

float fur_asin(float x_5)
{
    float ax_3 = min(abs(x_5), 1.0);
    float x2_ = (ax_3 * ax_3);
    float x4_ = (x2_ * x2_);
    float p01_1 = ((-0.001262491 * ax_3) + 0.00667009);
    float p23_1 = ((-0.017088126 * ax_3) + 0.03089188);
    float p45_1 = ((-0.050174303 * ax_3) + 0.08897899);
    float p67_1 = ((-0.2145988 * ax_3) + FUR_HALF_PI);
    float poly = ((((p01_1 * x2_) + p23_1) * x4_) + ((p45_1 * x2_) + p67_1));
    float r_15 = (FUR_HALF_PI - (sqrt((1.0 - ax_3)) * poly));
    return (((asuint(x_5) & 2147483648u) != 0u) ? -(abs(r_15)) : abs(r_15));
}

float fur_atan_poly(float t_1)
{
    float t2_ = (t_1 * t_1);
    float t4_ = (t2_ * t2_);
    float p01_2 = ((0.0029202348 * t_1) + -0.016366187);
    float p23_2 = ((0.043209206 * t_1) + -0.07552008);
    float p45_2 = ((0.10665919 * t_1) + -0.14211038);
    float p67_2 = ((0.19993772 * t_1) + -0.33333153);
    return ((((p01_2 * t2_) + p23_2) * t4_) + ((p45_2 * t2_) + p67_2));
}

float fur_atan2_(float y_1, float x_6)
{
    float r = (float)0;

    float ax_4 = abs(x_6);
    float ay = abs(y_1);
    float a_8 = (min(ax_4, ay) / max(max(ax_4, ay), 1.1754944e-38));
    float t_12 = (a_8 * a_8);
    const float _e10 = fur_atan_poly(t_12);
    r = (a_8 + (a_8 * (t_12 * _e10)));
    float _e15 = r;
    float _e17 = r;
    r = ((ay > ax_4) ? (FUR_HALF_PI - _e17) : _e15);
    float _e21 = r;
    float _e23 = r;
    r = ((x_6 < 0.0) ? (FUR_PI - _e23) : _e21);
    float _e28 = r;
    float _e29 = r;
    return (((asuint(y_1) & 2147483648u) != 0u) ? -(_e29) : _e28);
}

FurDirAngles ConstructFurDirAngles(float arg0, float arg1, float arg2, bool arg3) {
    FurDirAngles ret = (FurDirAngles)0;
    ret.theta_i = arg0;
    ret.theta_r = arg1;
    ret.phi = arg2;
    ret.ok = arg3;
    return ret;
}

FurDirAngles fur_angles_from_dirs(float3 wi, float3 wr, float3 u)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;

    FurDirAngles none = ConstructFurDirAngles(0.0, 0.0, 0.0, false);
    float ii = dot(wi, wi);
    float rr = dot(wr, wr);
    float uu = dot(u, u);
    const bool _e11 = fur_finite(ii);
    if (_e11) {
        const bool _e14 = fur_finite(rr);
        local_8 = _e14;
    } else {
        local_8 = false;
    }
    bool _e16 = local_8;
    if (_e16) {
        const bool _e19 = fur_finite(uu);
        local_9 = _e19;
    } else {
        local_9 = false;
    }
    bool _e21 = local_9;
    if (!(_e21)) {
        const FurDirAngles furdirangles = none;
        return furdirangles;
    }
    float ni = sqrt(ii);
    float nr = sqrt(rr);
    float nu = sqrt(uu);
    if (!((ni < 1.1754944e-38))) {
        local_10 = (nr < 1.1754944e-38);
    } else {
        local_10 = true;
    }
    bool _e33 = local_10;
    if (!(_e33)) {
        local_11 = (nu < 1.1754944e-38);
    } else {
        local_11 = true;
    }
    bool _e39 = local_11;
    if (_e39) {
        const FurDirAngles furdirangles_1 = none;
        return furdirangles_1;
    }
    float3 un = (u * (1.0 / nu));
    float a_9 = dot(wi, un);
    float b_3 = dot(wr, un);
    const float _e51 = fur_asin(clamp((a_9 * (1.0 / ni)), -1.0, 1.0));
    const float _e58 = fur_asin(clamp((b_3 * (1.0 / nr)), -1.0, 1.0));
    float y_6 = dot(un, cross(wi, wr));
    float x_18 = (dot(wi, wr) - (a_9 * b_3));
    const float _e64 = fur_atan2_(y_6, x_18);
    const FurDirAngles furdirangles_2 = ConstructFurDirAngles(_e51, _e58, abs(_e64), true);
    return furdirangles_2;
}

FurFamilies fur_eval_far_dirs(float3 wi_1, float3 wr_1, float3 u_1, float3 sigma_ca_3)
{
    const FurDirAngles _e4 = fur_angles_from_dirs(wi_1, wr_1, u_1);
    if (!(_e4.ok)) {
        const FurFamilies _e7 = fur_zero();
        const FurFamilies furfamilies_4 = _e7;
        return furfamilies_4;
    }
    const FurFamilies _e11 = fur_eval_far(_e4.theta_i, _e4.theta_r, _e4.phi, sigma_ca_3);
    const FurFamilies furfamilies_5 = _e11;
    return furfamilies_5;
}

typedef uint ret_Constructarray3_uint_[3];
ret_Constructarray3_uint_ Constructarray3_uint_(uint arg0, uint arg1, uint arg2) {
    uint ret[3] = { arg0, arg1, arg2 };
    return ret;
}

float fur_node(FurDensity d_1, uint row, uint j)
{
    const uint _e6 = fur_word(4u);
    uint n0_1 = (FUR_HEADER_HALVES + (3u * _e6));
    const uint _e9 = fur_n_plane_halves();
    const uint _e11 = fur_word(FUR_N_ABS_WORD);
    uint s0_1 = (n0_1 + (_e9 * _e11));
    uint starts[3] = Constructarray3_uint_(FUR_HEADER_HALVES, n0_1, s0_1);
    uint chans[3] = Constructarray3_uint_(3u, 4u, 2u);
    uint base = ((starts[min(uint(d_1.table), 2u)] + (((row * d_1.nodes) + j) * chans[min(uint(d_1.table), 2u)])) + d_1.channel);
    const float _e30 = fur_half(base);
    const float _e32 = fur_unbias(d_1.table);
    return (_e30 * _e32);
}

FurRows ConstructFurRows(FurDensity arg0, uint arg1, uint arg2, float arg3, float arg4, uint arg5) {
    FurRows ret = (FurRows)0;
    ret.d = arg0;
    ret.r0_ = arg1;
    ret.r1_ = arg2;
    ret.w = arg3;
    ret.origin = arg4;
    ret.weighting = arg5;
    return ret;
}

FurRows fur_rows(FurDensity d_2, uint row_1, float w, float origin)
{
    const FurRows furrows = ConstructFurRows(d_2, min(row_1, (d_2.rows - 1u)), min((row_1 + 1u), (d_2.rows - 1u)), w, origin, 0u);
    return furrows;
}

FurRows fur_rows_weighted(uint weighting, uint row_2, float w_1)
{
    const FurDensity _e8 = fur_density(((weighting == 2u) ? 9u : 6u));
    const FurRows furrows_1 = ConstructFurRows(_e8, min(row_2, (_e8.rows - 1u)), min((row_2 + 1u), (_e8.rows - 1u)), w_1, 0.0, weighting);
    return furrows_1;
}

float fur_rows_value(FurRows r_1, uint j_1)
{
    const float _e4 = fur_node(r_1.d, r_1.r0_, j_1);
    if ((r_1.w == 0.0)) {
        return _e4;
    }
    const float _e10 = fur_node(r_1.d, r_1.r1_, j_1);
    return (((1.0 - r_1.w) * _e4) + (r_1.w * _e10));
}

float fur_blended_prefix(FurRows r_2, FurDensity d_3, uint k_2)
{
    const float _e11 = fur_f32_at((d_3.prefix_at + (4u * ((r_2.r0_ * d_3.entries) + k_2))));
    if ((r_2.w == 0.0)) {
        return _e11;
    }
    const float _e23 = fur_f32_at((d_3.prefix_at + (4u * ((r_2.r1_ * d_3.entries) + k_2))));
    return (((1.0 - r_2.w) * _e11) + (r_2.w * _e23));
}

float fur_rows_prefix(FurRows r_3, uint k_3)
{
    const float _e3 = fur_blended_prefix(r_3, r_3.d, k_3);
    if ((r_3.weighting == 1u)) {
        const FurDensity _e8 = fur_density(9u);
        const float _e9 = fur_blended_prefix(r_3, _e8, k_3);
        return (_e3 - _e9);
    }
    return _e3;
}

float fur_rows_total(FurRows r_4)
{
    const float _e5 = fur_rows_prefix(r_4, (r_4.d.entries - 1u));
    return _e5;
}

float fur_linear_mass(float v0_, float v1_, float len)
{
    return ((0.5 * len) * (v0_ + v1_));
}

float fur_invert_linear(float v0_1, float v1_1, float len_1, float t_2)
{
    float s = 0.0;
    bool local_12 = (bool)0;
    bool local_13 = (bool)0;

    if (!((len_1 > 0.0))) {
        return 0.0;
    }
    if ((t_2 > 0.0)) {
        float disc = max(((v0_1 * v0_1) + (((2.0 * (v1_1 - v0_1)) * t_2) / len_1)), 0.0);
        float den = (v0_1 + sqrt(disc));
        if ((den > 0.0)) {
            s = clamp(((2.0 * t_2) / den), 0.0, len_1);
        } else {
            s = len_1;
        }
    }
    float inset = (len_1 * 9.536743e-7);
    if ((v0_1 <= 0.0)) {
        float _e36 = s;
        local_12 = (_e36 < inset);
    } else {
        local_12 = false;
    }
    bool _e39 = local_12;
    if (_e39) {
        return inset;
    }
    if ((v1_1 <= 0.0)) {
        float _e44 = s;
        local_13 = (_e44 > (len_1 - inset));
    } else {
        local_13 = false;
    }
    bool _e48 = local_13;
    if (_e48) {
        return (len_1 - inset);
    }
    float _e50 = s;
    return _e50;
}

float fur_weighted_linear_mass(float v0_2, float v1_2, float a_1, float b, float len_2)
{
    return ((len_2 * (((a_1 * v0_2) + (0.5 * ((a_1 * v1_2) + (b * v0_2)))) + (b * v1_2))) * 0.33333334);
}

float fur_invert_weighted_linear(float v0_3, float v1_3, float a_2, float b_1, float len_3, float t_3)
{
    float x_7 = 0.5;
    bool local_14 = (bool)0;
    float lo = 0.0;
    float hi = 1.0;
    uint k_4 = 0u;
    float next = (float)0;
    bool local_15 = (bool)0;
    bool local_16 = (bool)0;
    bool local_17 = (bool)0;

    if (!((len_3 > 0.0))) {
        return 0.0;
    }
    float q0_ = (a_2 * v0_3);
    float cb = ((a_2 * (v1_3 - v0_3)) + (v0_3 * (b_1 - a_2)));
    float cc = ((b_1 - a_2) * (v1_3 - v0_3));
    float q1_ = (b_1 * v1_3);
    float goal = (t_3 / len_3);
    float total_1 = ((q0_ + (0.5 * cb)) + (0.33333334 * cc));
    float lin = (0.5 * (q0_ + q1_));
    if ((total_1 > 0.0)) {
        local_14 = (lin > 0.0);
    } else {
        local_14 = false;
    }
    bool _e39 = local_14;
    if (_e39) {
        const float _e43 = fur_invert_linear(q0_, q1_, 1.0, (goal * (lin / total_1)));
        x_7 = _e43;
    }
    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e102 = k_4;
            k_4 = (_e102 + 1u);
        }
        loop_init_9 = false;
        uint _e50 = k_4;
        if ((_e50 < 8u)) {
        } else {
            break;
        }
        {
            float _e53 = x_7;
            float _e54 = x_7;
            float _e57 = x_7;
            float fx = ((_e53 * (q0_ + (_e54 * ((0.5 * cb) + ((_e57 * 0.33333334) * cc))))) - goal);
            if ((fx > 0.0)) {
                float _e68 = x_7;
                hi = _e68;
            } else {
                float _e69 = x_7;
                lo = _e69;
            }
            float _e70 = x_7;
            float _e71 = x_7;
            float d_7 = (q0_ + (_e70 * (cb + (_e71 * cc))));
            float _e76 = lo;
            float _e77 = hi;
            next = (0.5 * (_e76 + _e77));
            if ((d_7 > 0.0)) {
                float _e84 = x_7;
                float n_2 = (_e84 - (fx / d_7));
                float _e87 = lo;
                if ((n_2 >= _e87)) {
                    float _e91 = hi;
                    local_15 = (n_2 <= _e91);
                } else {
                    local_15 = false;
                }
                bool _e94 = local_15;
                if (_e94) {
                    next = n_2;
                }
            }
            float _e95 = next;
            float _e96 = x_7;
            bool done = (abs((_e95 - _e96)) <= 1.2e-7);
            float _e101 = next;
            x_7 = _e101;
            if (done) {
                break;
            }
        }
    }
    float _e105 = x_7;
    float s_2 = clamp((_e105 * len_3), 0.0, len_3);
    float inset_1 = (len_3 * 9.536743e-7);
    if ((q0_ <= 0.0)) {
        local_16 = (s_2 < inset_1);
    } else {
        local_16 = false;
    }
    bool _e117 = local_16;
    if (_e117) {
        return inset_1;
    }
    if ((q1_ <= 0.0)) {
        local_17 = (s_2 > (len_3 - inset_1));
    } else {
        local_17 = false;
    }
    bool _e125 = local_17;
    if (_e125) {
        return (len_3 - inset_1);
    }
    return s_2;
}

float2 fur_rows_weights(FurRows r_5, uint j_2)
{
    float inv = (1.0 / float((r_5.d.nodes - 1u)));
    float2 ab = float2((float(j_2) * inv), (float((j_2 + 1u)) * inv));
    if ((r_5.weighting == 1u)) {
        return float2((1.0 - ab.x), (1.0 - ab.y));
    }
    return ab;
}

float fur_rows_segment_mass(FurRows r_6, uint j_3, float v0_4, float v1_4)
{
    if ((r_6.weighting == 0u)) {
        const float _e9 = fur_linear_mass(v0_4, v1_4, r_6.d.step_);
        return _e9;
    }
    const float2 _e10 = fur_rows_weights(r_6, j_3);
    const float _e15 = fur_weighted_linear_mass(v0_4, v1_4, _e10.x, _e10.y, r_6.d.step_);
    return _e15;
}

float fur_rows_invert_segment(FurRows r_7, uint j_4, float v0_5, float v1_5, float t_4)
{
    if ((r_7.weighting == 0u)) {
        const float _e10 = fur_invert_linear(v0_5, v1_5, r_7.d.step_, t_4);
        return _e10;
    }
    const float2 _e11 = fur_rows_weights(r_7, j_4);
    const float _e16 = fur_invert_weighted_linear(v0_5, v1_5, _e11.x, _e11.y, r_7.d.step_, t_4);
    return _e16;
}

float fur_unit(float u_2)
{
    if ((u_2 > 0.0)) {
        return min(u_2, 0.99999994);
    }
    return 0.0;
}

float fur_rows_invert(FurRows r_8, float t_5)
{
    uint lo_1 = 0u;
    uint len_4 = (uint)0;
    float acc_2 = (float)0;
    float prev = (float)0;
    bool have_last = false;
    uint last_j = 0u;
    float last_v0_ = 0.0;
    float last_v1_ = 0.0;
    float last_m = 0.0;
    uint j_5 = (uint)0;

    len_4 = (r_8.d.entries - 1u);
    uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        uint _e9 = len_4;
        if ((_e9 <= 1u)) {
            break;
        }
        uint _e12 = len_4;
        uint half_1 = naga_div(_e12, 2u);
        uint _e15 = lo_1;
        uint _e16 = lo_1;
        uint _e18 = lo_1;
        const float _e20 = fur_rows_prefix(r_8, (_e18 + half_1));
        lo_1 = ((_e20 < t_5) ? (_e16 + half_1) : _e15);
        uint _e23 = len_4;
        len_4 = (_e23 - half_1);
    }
    uint _e25 = lo_1;
    uint first = (_e25 * r_8.d.block);
    uint end = min((first + r_8.d.block), (r_8.d.nodes - 1u));
    uint _e37 = lo_1;
    const float _e38 = fur_rows_prefix(r_8, _e37);
    acc_2 = _e38;
    const float _e40 = fur_rows_value(r_8, first);
    prev = _e40;
    j_5 = first;
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_10 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_10) {
            uint _e85 = j_5;
            j_5 = (_e85 + 1u);
        }
        loop_init_10 = false;
        uint _e53 = j_5;
        if ((_e53 < end)) {
        } else {
            break;
        }
        {
            uint _e55 = j_5;
            const float _e58 = fur_rows_value(r_8, (_e55 + 1u));
            uint _e59 = j_5;
            float _e60 = prev;
            const float _e61 = fur_rows_segment_mass(r_8, _e59, _e60, _e58);
            if ((_e61 > 0.0)) {
                float _e64 = acc_2;
                if (((t_5 - _e64) <= _e61)) {
                    uint _e67 = j_5;
                    float _e68 = prev;
                    float _e69 = acc_2;
                    const float _e71 = fur_rows_invert_segment(r_8, _e67, _e68, _e58, (t_5 - _e69));
                    uint _e73 = j_5;
                    return ((r_8.origin + (float(_e73) * r_8.d.step_)) + _e71);
                }
                have_last = true;
                uint _e81 = j_5;
                last_j = _e81;
                float _e82 = prev;
                last_v0_ = _e82;
                last_v1_ = _e58;
                last_m = _e61;
            }
            float _e83 = acc_2;
            acc_2 = (_e83 + _e61);
            prev = _e58;
        }
    }
    bool _e88 = have_last;
    if (_e88) {
        float _e89 = last_m;
        float _e92 = last_v0_;
        float _e93 = last_v1_;
        float whole = ((r_8.weighting == 0u) ? (r_8.d.step_ * (_e92 + _e93)) : _e89);
        uint _e100 = last_j;
        float _e101 = last_v0_;
        float _e102 = last_v1_;
        const float _e103 = fur_rows_invert_segment(r_8, _e100, _e101, _e102, whole);
        uint _e105 = last_j;
        return ((r_8.origin + (float(_e105) * r_8.d.step_)) + _e103);
    }
    return (r_8.origin + (float(end) * r_8.d.step_));
}

float fur_rows_invert_between(FurRows r_9, float t0_, float t1_, float u_3)
{
    float inset_2 = ((t1_ - t0_) * 9.536743e-7);
    const float _e7 = fur_unit(u_3);
    float t_13 = clamp((t0_ + (_e7 * (t1_ - t0_))), (t0_ + inset_2), (t1_ - inset_2));
    const float _e14 = fur_rows_invert(r_9, t_13);
    return _e14;
}

float fur_pole_keep(float cos_theta_i)
{
    float c_3 = max(cos_theta_i, 1e-6);
    return min(((c_3 * c_3) * 10000.0), 1.0);
}

float fur_sliver_keep(float s_in)
{
    float s_3 = abs(s_in);
    if (!((s_3 < FUR_POLE_SLIVER))) {
        return 1.0;
    }
    float s2_ = (s_3 * s_3);
    return min(((s2_ * (1.0 - (s2_ * 0.33333334))) * 10000.0), 1.0);
}

typedef float ret_Constructarray3_float_[3];
ret_Constructarray3_float_ Constructarray3_float_(float arg0, float arg1, float arg2) {
    float ret[3] = { arg0, arg1, arg2 };
    return ret;
}

float fur_sliver_piece_mass(float v0_6, float v1_6, float len0_, float x0_, float pole, float len_5)
{
    bool local_18 = (bool)0;
    float acc_3 = 0.0;
    uint k_5 = 0u;

    if ((len_5 > 0.0)) {
        local_18 = (len0_ > 0.0);
    } else {
        local_18 = false;
    }
    bool _e13 = local_18;
    if (!(_e13)) {
        return 0.0;
    }
    float slope = ((v1_6 - v0_6) / len0_);
    float t_14[3] = Constructarray3_float_(0.11270166, 0.5, 0.8872983);
    float w_5[3] = Constructarray3_float_(0.2777778, 0.44444445, 0.2777778);
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e47 = k_5;
            k_5 = (_e47 + 1u);
        }
        loop_init_11 = false;
        uint _e30 = k_5;
        if ((_e30 < 3u)) {
        } else {
            break;
        }
        {
            uint _e33 = k_5;
            float d_8 = (t_14[min(uint(_e33), 2u)] * len_5);
            float _e36 = acc_3;
            uint _e37 = k_5;
            const float _e44 = fur_sliver_keep(((x0_ - pole) + d_8));
            acc_3 = (_e36 + ((w_5[min(uint(_e37), 2u)] * (v0_6 + (slope * d_8))) * _e44));
        }
    }
    float _e50 = acc_3;
    return (_e50 * len_5);
}

float fur_invert_sliver_piece(float v0_7, float v1_7, float len_6, float x0_1, float pole_1, float t_6)
{
    bool local_19 = (bool)0;
    float lo_2 = 0.0;
    float hi_1 = (float)0;
    float d_4 = (float)0;
    uint k_6 = 0u;
    float next_1 = (float)0;
    bool local_20 = (bool)0;

    const float _e6 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, len_6);
    if (!(!((_e6 > 0.0)))) {
        local_19 = !((t_6 > 0.0));
    } else {
        local_19 = true;
    }
    bool _e17 = local_19;
    if (_e17) {
        return 0.0;
    }
    if (!((t_6 < _e6))) {
        return len_6;
    }
    float slope_1 = ((v1_7 - v0_7) / len_6);
    hi_1 = len_6;
    d_4 = (len_6 * (t_6 / _e6));
    uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
        loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e76 = k_6;
            k_6 = (_e76 + 1u);
        }
        loop_init_12 = false;
        uint _e31 = k_6;
        if ((_e31 < 16u)) {
        } else {
            break;
        }
        {
            float _e34 = d_4;
            const float _e35 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, _e34);
            float f_8 = (_e35 - t_6);
            if ((f_8 > 0.0)) {
                float _e39 = d_4;
                hi_1 = _e39;
            } else {
                float _e40 = d_4;
                lo_2 = _e40;
            }
            float _e41 = d_4;
            float _e45 = d_4;
            const float _e47 = fur_sliver_keep(((x0_1 - pole_1) + _e45));
            float dens = ((v0_7 + (slope_1 * _e41)) * _e47);
            float _e49 = lo_2;
            float _e50 = hi_1;
            next_1 = (0.5 * (_e49 + _e50));
            if ((dens > 0.0)) {
                float _e57 = d_4;
                float n_3 = (_e57 - (f_8 / dens));
                float _e60 = lo_2;
                if ((n_3 >= _e60)) {
                    float _e64 = hi_1;
                    local_20 = (n_3 <= _e64);
                } else {
                    local_20 = false;
                }
                bool _e67 = local_20;
                if (_e67) {
                    next_1 = n_3;
                }
            }
            float _e68 = next_1;
            float _e69 = d_4;
            bool done_1 = (abs((_e68 - _e69)) <= (1.2e-7 * len_6));
            float _e75 = next_1;
            d_4 = _e75;
            if (done_1) {
                break;
            }
        }
    }
    float _e79 = d_4;
    return clamp(_e79, 0.0, len_6);
}

float3 fur_rows_sliver(FurRows r_10, FurAxis ax, float a_3, float b_2, float pole_2, float t_7)
{
    float off = 0.0;
    float3 out_1 = (float3)0;
    uint j_6 = (uint)0;
    bool local_21 = (bool)0;
    bool local_22 = (bool)0;

    const FurLoc _e6 = fur_locate(ax, a_3);
    const FurLoc _e7 = fur_locate(ax, b_2);
    float at_2 = (a_3 - pole_2);
    out_1 = float3(0.0, 0.0, b_2);
    j_6 = _e6.i;
    uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e92 = j_6;
            j_6 = (_e92 + 1u);
        }
        loop_init_13 = false;
        uint _e17 = j_6;
        if ((_e17 <= _e7.i)) {
        } else {
            break;
        }
        {
            uint _e21 = j_6;
            float w0_2 = ((_e21 == _e6.i) ? _e6.w : 0.0);
            uint _e27 = j_6;
            float w1_2 = ((_e27 == _e7.i) ? _e7.w : 1.0);
            if ((w1_2 > w0_2)) {
                uint _e33 = j_6;
                const float _e34 = fur_rows_value(r_10, _e33);
                uint _e35 = j_6;
                const float _e38 = fur_rows_value(r_10, (_e35 + 1u));
                float len_7 = ((w1_2 - w0_2) * r_10.d.step_);
                float v0_9 = (_e34 + ((_e38 - _e34) * w0_2));
                float v1_9 = (_e34 + ((_e38 - _e34) * w1_2));
                float _e49 = off;
                const float _e52 = fur_sliver_piece_mass(v0_9, v1_9, len_7, (at_2 + _e49), 0.0, len_7);
                if ((t_7 >= 0.0)) {
                    local_21 = (_e52 > 0.0);
                } else {
                    local_21 = false;
                }
                bool _e60 = local_21;
                if (_e60) {
                    float _e64 = out_1.y;
                    local_22 = ((t_7 - _e64) <= _e52);
                } else {
                    local_22 = false;
                }
                bool _e68 = local_22;
                if (_e68) {
                    float _e70 = off;
                    float _e71 = off;
                    float _e75 = out_1.y;
                    const float _e77 = fur_invert_sliver_piece(v0_9, v1_9, len_7, (at_2 + _e71), 0.0, (t_7 - _e75));
                    out_1.z = (a_3 + (_e70 + _e77));
                    float3 _e80 = out_1;
                    return _e80;
                }
                float _e83 = out_1.x;
                const float _e84 = fur_linear_mass(v0_9, v1_9, len_7);
                out_1.x = (_e83 + _e84);
                float _e88 = out_1.y;
                out_1.y = (_e88 + _e52);
                float _e90 = off;
                off = (_e90 + len_7);
            }
        }
    }
    float3 _e95 = out_1;
    return _e95;
}

FurRange ConstructFurRange(float arg0, float arg1, float arg2, float arg3, float4 arg4) {
    FurRange ret = (FurRange)0;
    ret.lo = arg0;
    ret.hi = arg1;
    ret.start = arg2;
    ret.raw = arg3;
    ret.s = arg4;
    return ret;
}

FurRange fur_rows_range(FurRows r_11, FurAxis ax_1, float lo_3, float hi_2, float start, float raw)
{
    const float3 _e9 = fur_rows_sliver(r_11, ax_1, lo_3, (lo_3 + FUR_POLE_SLIVER), lo_3, -1.0);
    const float3 _e13 = fur_rows_sliver(r_11, ax_1, (hi_2 - FUR_POLE_SLIVER), hi_2, hi_2, -1.0);
    const FurRange furrange = ConstructFurRange(lo_3, hi_2, start, raw, float4(_e9.x, _e9.y, _e13.x, _e13.y));
    return furrange;
}

float fur_range_kept(FurRange g_1)
{
    return ((max(((g_1.raw - g_1.s.x) - g_1.s.z), 0.0) + g_1.s.y) + g_1.s.w);
}

float fur_rows_invert_kept(FurRows r_12, FurAxis ax_2, FurRange g_2, float u_4)
{
    bool local_23 = (bool)0;

    const float _e4 = fur_range_kept(g_2);
    float inset_3 = (_e4 * 9.536743e-7);
    const float _e7 = fur_unit(u_4);
    float t0_1 = clamp((_e7 * _e4), inset_3, (_e4 - inset_3));
    if ((t0_1 < g_2.s.y)) {
        const float3 _e19 = fur_rows_sliver(r_12, ax_2, g_2.lo, (g_2.lo + FUR_POLE_SLIVER), g_2.lo, t0_1);
        return _e19.z;
    }
    float mid = max(((g_2.raw - g_2.s.x) - g_2.s.z), 0.0);
    float t_15 = (t0_1 - g_2.s.y);
    if (!((t_15 <= mid))) {
        local_23 = !((g_2.s.w > 0.0));
    } else {
        local_23 = true;
    }
    bool _e43 = local_23;
    if (_e43) {
        const float _e50 = fur_rows_invert(r_12, ((g_2.start + g_2.s.x) + min(t_15, mid)));
        return _e50;
    }
    const float3 _e57 = fur_rows_sliver(r_12, ax_2, (g_2.hi - FUR_POLE_SLIVER), g_2.hi, g_2.hi, (t_15 - mid));
    return _e57.z;
}

FurAxis fur_sum_axis()
{
    const uint _e3 = fur_word(4u);
    const FurAxis _e4 = fur_axis(true, 0.15915494, _e3);
    const FurAxis furaxis_1 = _e4;
    return furaxis_1;
}

FurMAt ConstructFurMAt(float3 arg0, float3 arg1) {
    FurMAt ret = (FurMAt)0;
    ret.cdf = arg0;
    ret.value = arg1;
    return ret;
}

FurMAt fur_m_at(FurLoc l_1)
{
    FurMAt out_2 = ConstructFurMAt((0.0).xxx, (0.0).xxx);
    uint g_3 = 0u;

    const FurDensity _e2 = fur_density(0u);
    float off_1 = (l_1.w * _e2.step_);
    uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e45 = g_3;
            g_3 = (_e45 + 1u);
        }
        loop_init_14 = false;
        uint _e14 = g_3;
        if ((_e14 < 3u)) {
        } else {
            break;
        }
        {
            uint _e17 = g_3;
            const FurDensity _e18 = fur_density(_e17);
            const float _e21 = fur_node(_e18, 0u, l_1.i);
            const float _e26 = fur_node(_e18, 0u, (l_1.i + 1u));
            float at_3 = (_e21 + ((_e26 - _e21) * l_1.w));
            uint _e32 = g_3;
            const float _e39 = fur_f32_at((_e18.prefix_at + (4u * l_1.i)));
            const float _e40 = fur_linear_mass(_e21, at_3, off_1);
            out_2.cdf[min(uint(_e32), 2u)] = (_e39 + _e40);
            uint _e43 = g_3;
            out_2.value[min(uint(_e43), 2u)] = at_3;
        }
    }
    FurMAt _e48 = out_2;
    const FurMAt furmat = _e48;
    return furmat;
}

float3 fur_m_cdf(float x_8)
{
    const FurAxis _e1 = fur_sum_axis();
    const FurLoc _e2 = fur_locate(_e1, x_8);
    const FurMAt _e3 = fur_m_at(_e2);
    return _e3.cdf;
}

float fur_row_total(FurDensity d_5, FurLoc l_2)
{
    const float _e17 = fur_f32_at((d_5.prefix_at + (4u * (((min(l_2.i, (d_5.rows - 1u)) * d_5.entries) + d_5.entries) - 1u))));
    const float _e35 = fur_f32_at((d_5.prefix_at + (4u * (((min((l_2.i + 1u), (d_5.rows - 1u)) * d_5.entries) + d_5.entries) - 1u))));
    return (_e17 + ((_e35 - _e17) * l_2.w));
}

float fur_positive(float v)
{
    bool local_24 = (bool)0;

    const bool _e1 = fur_finite(v);
    if (_e1) {
        local_24 = (v > 0.0);
    } else {
        local_24 = false;
    }
    bool _e7 = local_24;
    return (_e7 ? v : 0.0);
}

FurAxis fur_ms_i_axis()
{
    const uint _e3 = fur_word(7u);
    const FurAxis _e4 = fur_axis(true, 0.31830987, _e3);
    const FurAxis furaxis_2 = _e4;
    return furaxis_2;
}

FurRows fur_ms_rows(uint half_, float theta_r_4)
{
    const uint _e5 = fur_word(8u);
    const FurAxis _e6 = fur_axis(true, 0.31830987, _e5);
    const FurLoc _e7 = fur_locate(_e6, theta_r_4);
    const FurDensity _e10 = fur_density((7u + half_));
    const FurRows _e14 = fur_rows(_e10, _e7.i, _e7.w, -1.5707964);
    const FurRows furrows_2 = _e14;
    return furrows_2;
}

typedef float ret_Constructarray5_float_[5];
ret_Constructarray5_float_ Constructarray5_float_(float arg0, float arg1, float arg2, float arg3, float arg4) {
    float ret[5] = { arg0, arg1, arg2, arg3, arg4 };
    return ret;
}

FurParts ConstructFurParts(float arg0[5], FurRange arg1[5]) {
    FurParts ret = (FurParts)0;
    ret.a = arg0;
    ret.ranges = arg1;
    return ret;
}

FurParts fur_parts(float theta_r_5)
{
    FurRange ranges[5] = (FurRange[5])0;
    uint g_4 = 0u;
    uint x_9 = 0u;

    float lo_x = (theta_r_5 - FUR_HALF_PI);
    float hi_x = (theta_r_5 + FUR_HALF_PI);
    const float3 _e5 = fur_m_cdf(lo_x);
    const float3 _e6 = fur_m_cdf(hi_x);
    float3 mass = max((_e6 - _e5), (0.0).xxx);
    const uint _e14 = fur_word(5u);
    const FurAxis _e15 = fur_axis(false, 0.63661975, _e14);
    const FurLoc _e17 = fur_locate(_e15, abs(theta_r_5));
    const FurDensity _e19 = fur_density(6u);
    const float _e20 = fur_row_total(_e19, _e17);
    const FurDensity _e22 = fur_density(9u);
    const float _e23 = fur_row_total(_e22, _e17);
    uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
    bool loop_init_15 = true;
    while(true) {
        if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_15) {
            uint _e44 = g_4;
            g_4 = (_e44 + 1u);
        }
        loop_init_15 = false;
        uint _e27 = g_4;
        if ((_e27 < 3u)) {
        } else {
            break;
        }
        {
            uint _e30 = g_4;
            const FurDensity _e31 = fur_density(_e30);
            const FurRows _e35 = fur_rows(_e31, 0u, 0.0, -3.1415927);
            uint _e36 = g_4;
            const FurAxis _e38 = fur_sum_axis();
            uint _e39 = g_4;
            uint _e41 = g_4;
            const FurRange _e43 = fur_rows_range(_e35, _e38, lo_x, hi_x, _e5[min(uint(_e39), 2u)], mass[min(uint(_e41), 2u)]);
            ranges[min(uint(_e36), 4u)] = _e43;
        }
    }
    uint2 loop_bound_17 = uint2(4294967295u, 4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (all(loop_bound_17 == uint2(0u, 0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e64 = x_9;
            x_9 = (_e64 + 1u);
        }
        loop_init_16 = false;
        uint _e49 = x_9;
        if ((_e49 < 2u)) {
        } else {
            break;
        }
        {
            uint _e52 = x_9;
            const FurRows _e53 = fur_ms_rows(_e52, theta_r_5);
            uint _e55 = x_9;
            const FurAxis _e58 = fur_ms_i_axis();
            const float _e62 = fur_rows_total(_e53);
            const FurRange _e63 = fur_rows_range(_e53, _e58, -1.5707964, FUR_HALF_PI, 0.0, _e62);
            ranges[min(uint((3u + _e55)), 4u)] = _e63;
        }
    }
    FurRange _e68 = ranges[0];
    const float _e69 = fur_range_kept(_e68);
    FurRange _e71 = ranges[1];
    const float _e72 = fur_range_kept(_e71);
    FurRange _e74 = ranges[2];
    const float _e75 = fur_range_kept(_e74);
    const float3 _e77 = fur_sphere_norms(theta_r_5);
    float3 kept = (float3(_e69, _e72, _e75) * _e77);
    const FurDensity _e83 = fur_density(3u);
    const float _e84 = fur_row_total(_e83, _e17);
    const float _e86 = fur_positive(((2.0 * kept.x) * _e84));
    const FurDensity _e91 = fur_density(4u);
    const float _e92 = fur_row_total(_e91, _e17);
    const float _e94 = fur_positive(((2.0 * kept.y) * _e92));
    const FurDensity _e99 = fur_density(5u);
    const float _e100 = fur_row_total(_e99, _e17);
    const float _e102 = fur_positive(((2.0 * kept.z) * _e100));
    FurRange _e104 = ranges[3];
    const float _e105 = fur_range_kept(_e104);
    const float _e110 = fur_positive(((2.0 * _e105) * (_e20 - _e23)));
    FurRange _e112 = ranges[4];
    const float _e113 = fur_range_kept(_e112);
    const float _e117 = fur_positive(((2.0 * _e113) * _e23));
    float a_10[5] = Constructarray5_float_(_e86, _e94, _e102, _e110, _e117);
    FurRange _e119[5] = ranges;
    const FurParts furparts = ConstructFurParts(a_10, _e119);
    return furparts;
}

float fur_density_of(FurLookups l_3, float w_2, float cos_theta_i_1)
{
    if (!((w_2 > 0.0))) {
        return 0.0;
    }
    float ms_1 = (l_3.ms[0] + (l_3.front * (l_3.ms[1] - l_3.ms[0])));
    float p_5 = ((((l_3.m[0] * l_3.n0_[0]) + (l_3.m[1] * l_3.n0_[1])) + (l_3.m[2] * l_3.n0_[2])) + (ms_1 * l_3.n0_[3]));
    const float _e38 = fur_pole_keep(cos_theta_i_1);
    float pg = (p_5 * _e38);
    const float _e44 = fur_positive(((pg / w_2) / max(cos_theta_i_1, 1e-6)));
    return _e44;
}

float fur_pdf_far(float theta_i_3, float theta_r_6, float phi_2, float3 sigma_ca_4)
{
    const bool _e4 = fur_valid(theta_i_3, theta_r_6, phi_2);
    if (!(_e4)) {
        return 0.0;
    }
    const FurParts _e7 = fur_parts(theta_r_6);
    float w_6 = ((((_e7.a[0] + _e7.a[1]) + _e7.a[2]) + _e7.a[3]) + _e7.a[4]);
    const FurLookups _e22 = fur_lookups(theta_i_3, theta_r_6, phi_2, sigma_ca_4);
    const float _e23 = fur_cos_within_half_pi(theta_i_3);
    const float _e24 = fur_density_of(_e22, w_6, _e23);
    return _e24;
}

FurSample ConstructFurSample(float arg0, float arg1, float arg2, float3 arg3, uint arg4, bool arg5) {
    FurSample ret = (FurSample)0;
    ret.theta_i = arg0;
    ret.phi = arg1;
    ret.pdf = arg2;
    ret.weight = arg3;
    ret.family = arg4;
    ret.ok = arg5;
    return ret;
}

FurSample fur_sample_far(float theta_r_7, float3 u_5, float3 sigma_ca_5)
{
    FurSample out_3 = ConstructFurSample(0.0, 0.0, 0.0, (0.0).xxx, 0u, false);
    bool local_25 = (bool)0;
    float total = 0.0;
    uint k_7 = 0u;
    float acc_4 = 0.0;
    uint c_1 = 5u;
    float u0_ = 0.0;
    uint last = 5u;
    uint k_8 = 0u;
    float theta_i_4 = 0.0;
    FurRows nrows = (FurRows)0;
    bool local_26 = (bool)0;

    const bool _e12 = fur_finite(theta_r_7);
    if (_e12) {
        local_25 = (abs(theta_r_7) <= FUR_HALF_PI);
    } else {
        local_25 = false;
    }
    bool _e19 = local_25;
    if (!(_e19)) {
        FurSample _e21 = out_3;
        const FurSample fursample = _e21;
        return fursample;
    }
    const FurParts _e22 = fur_parts(theta_r_7);
    uint2 loop_bound_18 = uint2(4294967295u, 4294967295u);
    bool loop_init_17 = true;
    while(true) {
        if (all(loop_bound_18 == uint2(0u, 0u))) { break; }
        loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
        if (!loop_init_17) {
            uint _e35 = k_7;
            k_7 = (_e35 + 1u);
        }
        loop_init_17 = false;
        uint _e27 = k_7;
        if ((_e27 < 5u)) {
        } else {
            break;
        }
        {
            float _e30 = total;
            uint _e32 = k_7;
            total = (_e30 + _e22.a[min(uint(_e32), 4u)]);
        }
    }
    float _e38 = total;
    if (!((_e38 > 0.0))) {
        FurSample _e42 = out_3;
        const FurSample fursample_1 = _e42;
        return fursample_1;
    }
    const float _e44 = fur_unit(u_5.x);
    float _e45 = total;
    float target_mass = (_e44 * _e45);
    uint2 loop_bound_19 = uint2(4294967295u, 4294967295u);
    bool loop_init_18 = true;
    while(true) {
        if (all(loop_bound_19 == uint2(0u, 0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_18) {
            uint _e77 = k_8;
            k_8 = (_e77 + 1u);
        }
        loop_init_18 = false;
        uint _e57 = k_8;
        if ((_e57 < 5u)) {
        } else {
            break;
        }
        {
            uint _e61 = k_8;
            float wk = _e22.a[min(uint(_e61), 4u)];
            if (!((wk > 0.0))) {
                continue;
            }
            uint _e66 = k_8;
            last = _e66;
            float _e67 = acc_4;
            if ((target_mass < (_e67 + wk))) {
                uint _e70 = k_8;
                c_1 = _e70;
                float _e71 = acc_4;
                const float _e74 = fur_unit(((target_mass - _e71) / wk));
                u0_ = _e74;
                break;
            }
            float _e75 = acc_4;
            acc_4 = (_e75 + wk);
        }
    }
    uint _e80 = c_1;
    if ((_e80 == 5u)) {
        uint _e83 = last;
        c_1 = _e83;
        u0_ = 0.99999994;
    }
    float total_weight = ((((_e22.a[0] + _e22.a[1]) + _e22.a[2]) + _e22.a[3]) + _e22.a[4]);
    float _e99 = u0_;
    bool negative = (_e99 < 0.5);
    uint _e104 = c_1;
    if ((_e104 < 3u)) {
        uint _e107 = c_1;
        const FurDensity _e108 = fur_density(_e107);
        const FurRows _e112 = fur_rows(_e108, 0u, 0.0, -3.1415927);
        const FurAxis _e113 = fur_sum_axis();
        uint _e115 = c_1;
        const float _e118 = fur_rows_invert_kept(_e112, _e113, _e22.ranges[min(uint(_e115), 4u)], u_5.y);
        theta_i_4 = clamp((_e118 - theta_r_7), -1.5707964, FUR_HALF_PI);
    } else {
        uint _e123 = c_1;
        const FurRows _e126 = fur_ms_rows((_e123 - 3u), theta_r_7);
        const FurAxis _e127 = fur_ms_i_axis();
        uint _e129 = c_1;
        const float _e132 = fur_rows_invert_kept(_e126, _e127, _e22.ranges[min(uint(_e129), 4u)], u_5.y);
        theta_i_4 = clamp(_e132, -1.5707964, FUR_HALF_PI);
    }
    uint _e136 = c_1;
    uint family = min(_e136, 3u);
    const uint _e142 = fur_word(5u);
    const FurAxis _e143 = fur_axis(false, 0.63661975, _e142);
    const FurLoc _e145 = fur_locate(_e143, abs(theta_r_7));
    const FurDensity _e148 = fur_density((3u + family));
    const FurRows _e152 = fur_rows(_e148, _e145.i, _e145.w, 0.0);
    nrows = _e152;
    uint _e154 = c_1;
    if ((_e154 >= 3u)) {
        uint _e157 = c_1;
        const FurRows _e162 = fur_rows_weighted((_e157 - 2u), _e145.i, _e145.w);
        nrows = _e162;
    }
    FurRows _e163 = nrows;
    FurRows _e165 = nrows;
    const float _e166 = fur_rows_total(_e165);
    const float _e168 = fur_rows_invert_between(_e163, 0.0, _e166, u_5.z);
    float abs_phi_1 = clamp(_e168, 0.0, FUR_PI);
    const float _e174 = fur_wrap_angle((negative ? -(abs_phi_1) : abs_phi_1));
    float _e175 = theta_i_4;
    const FurLookups _e176 = fur_lookups(_e175, theta_r_7, _e174, sigma_ca_5);
    float _e177 = theta_i_4;
    const float _e178 = fur_cos_within_half_pi(_e177);
    const float _e179 = fur_density_of(_e176, total_weight, _e178);
    if ((_e179 > 0.0)) {
        const bool _e184 = fur_finite(_e179);
        local_26 = _e184;
    } else {
        local_26 = false;
    }
    bool _e186 = local_26;
    if (!(_e186)) {
        FurSample _e188 = out_3;
        const FurSample fursample_2 = _e188;
        return fursample_2;
    }
    const FurFamilies _e189 = fur_assemble(_e176);
    float _e190 = theta_i_4;
    float k_19 = (max(cos(_e190), 0.0) / _e179);
    float _e195 = theta_i_4;
    out_3 = ConstructFurSample(_e195, _e174, _e179, max((_e189.total * k_19), (0.0).xxx), family, true);
    FurSample _e203 = out_3;
    const FurSample fursample_3 = _e203;
    return fursample_3;
}

float fur_dual_half(uint h_1)
{
    uint _e7 = asuint(fur_dual.Load((FUR_DUAL_HEADER_WORDS + (h_1 >> 1u))*4));
    float2 pair = float2(f16tof32(_e7), f16tof32((_e7) >> 16));
    return (((h_1 & 1u) == 1u) ? pair.y : pair.x);
}

float3 fur_dual_rgb(uint3 a_4, uint h_2)
{
    uint3 n_4 = ((a_4 * FUR_DUAL_NODE_HALVES) + (h_2).xxx);
    const float _e7 = fur_dual_half(n_4.x);
    const float _e9 = fur_dual_half(n_4.y);
    const float _e11 = fur_dual_half(n_4.z);
    return float3(_e7, _e9, _e11);
}

float3 fur_dual_sigma_node(uint3 k_9)
{
    float3 v_3 = ((float3(k_9) / (15.0).xxx) * 0.997009);
    return ((k_9 >= (15u).xxx) ? (1000.0).xxx : ((FUR_DUAL_KNEE * v_3) / ((1.0).xxx - v_3)));
}

FurDualColour ConstructFurDualColour(uint3 arg0, float3 arg1) {
    FurDualColour ret = (FurDualColour)0;
    ret.node = arg0;
    ret.w = arg1;
    return ret;
}

FurDualColour fur_dual_locate(float3 sigma_in)
{
    uint3 k_10 = (uint3)0;
    float3 w_3 = (float3)0;

    const bool3 _e9 = fur_is_nan3_(sigma_in);
    float3 s_4 = (_e9 ? (0.0).xxx : min(max(sigma_in, (0.0).xxx), (1000.0).xxx));
    float3 coord = min(((s_4 / (s_4 + (3.0).xxx)) / (0.997009).xxx), (1.0).xxx);
    float3 u_9 = clamp((coord * 15.0), (0.0).xxx, (15.0).xxx);
    k_10 = min(naga_f2u32(u_9), (14u).xxx);
    uint3 _e32 = k_10;
    const float3 _e33 = fur_dual_sigma_node(_e32);
    float3 lo_4 = sqrt(_e33);
    uint3 _e35 = k_10;
    const float3 _e39 = fur_dual_sigma_node((_e35 + (1u).xxx));
    float3 hi_3 = sqrt(_e39);
    w_3 = clamp(((sqrt(s_4) - lo_4) / (hi_3 - lo_4)), (0.0).xxx, (1.0).xxx);
    float3 _e51 = w_3;
    float3 _e54 = w_3;
    const bool3 _e55 = fur_is_nan3_(_e54);
    float3 _e56 = w_3;
    w_3 = ((_e55 | (_e56 < (0.0001).xxx)) ? (0.0).xxx : _e51);
    float3 _e62 = w_3;
    uint3 _e66 = k_10;
    bool3 up = ((_e62 > (0.9999).xxx) & ((_e66 + (2u).xxx) < (16u).xxx));
    uint3 _e74 = k_10;
    uint3 _e75 = k_10;
    k_10 = (up ? (_e75 + (1u).xxx) : _e74);
    float3 _e80 = w_3;
    w_3 = (up ? (0.0).xxx : _e80);
    float3 _e84 = w_3;
    float3 _e87 = w_3;
    w_3 = ((_e87 > (0.9999).xxx) ? (1.0).xxx : _e84);
    uint3 _e92 = k_10;
    float3 _e93 = w_3;
    const FurDualColour furdualcolour = ConstructFurDualColour(_e92, _e93);
    return furdualcolour;
}

bool fur_is_nan(float x_10)
{
    return ((asuint(x_10) & 2147483647u) > 2139095040u);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

FurLoc fur_dual_theta(float theta)
{
    float t_8 = (float)0;

    t_8 = (((theta + FUR_HALF_PI) * FUR_DUAL_THETA_SCALE) - 0.5);
    float _e8 = t_8;
    float _e9 = t_8;
    t_8 = ((_e9 > 0.0) ? _e8 : 0.0);
    float _e14 = t_8;
    t_8 = min(_e14, 63.0);
    float _e17 = t_8;
    uint k_20 = min(naga_f2u32(_e17), 62u);
    float _e21 = t_8;
    const FurLoc furloc_1 = ConstructFurLoc(k_20, (_e21 - float(k_20)));
    return furloc_1;
}

float3 fur_dual_node(uint3 a_5, uint k_11, uint f_3)
{
    const float3 _e6 = fur_dual_rgb(a_5, ((k_11 * FUR_DUAL_FIELDS) + f_3));
    return _e6;
}

float3 fur_dual_field(FurLoc l_4, uint f_4)
{
    uint3 lo_5 = fur_dual_at.node;
    const float3 _e6 = fur_dual_node(lo_5, l_4.i, f_4);
    const float3 _e10 = fur_dual_node(lo_5, (l_4.i + 1u), f_4);
    const float3 _e15 = fur_dual_node((lo_5 + (1u).xxx), l_4.i, f_4);
    const float3 _e22 = fur_dual_node((lo_5 + (1u).xxx), (l_4.i + 1u), f_4);
    float3 v0_10 = (_e6 + ((_e10 - _e6) * l_4.w));
    float3 v1_10 = (_e15 + ((_e22 - _e15) * l_4.w));
    float3 _e34 = fur_dual_at.w;
    return (v0_10 + ((v1_10 - v0_10) * _e34));
}

float3 fur_dual_ng_at(uint3 a_6, uint g_5, FurLoc l_5, FurLoc p)
{
    uint row0_ = ((((g_5 * FUR_DUAL_THETA_NODES) + l_5.i) * FUR_DUAL_PHI_NODES) + p.i);
    uint row1_ = (row0_ + FUR_DUAL_PHI_NODES);
    const float3 _e16 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row0_));
    const float3 _e21 = fur_dual_rgb(a_6, ((FUR_DUAL_NG_START + row0_) + 1u));
    const float3 _e24 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row1_));
    const float3 _e29 = fur_dual_rgb(a_6, ((FUR_DUAL_NG_START + row1_) + 1u));
    float w_7 = l_5.w;
    float v_4 = p.w;
    return ((((((1.0 - w_7) * (1.0 - v_4)) * _e16) + (((1.0 - w_7) * v_4) * _e21)) + ((w_7 * (1.0 - v_4)) * _e24)) + ((w_7 * v_4) * _e29));
}

float3 fur_dual_ng(uint g_6, FurLoc l_6, FurLoc p_1)
{
    uint3 _e5 = fur_dual_at.node;
    const float3 _e6 = fur_dual_ng_at(_e5, g_6, l_6, p_1);
    uint3 _e9 = fur_dual_at.node;
    const float3 _e13 = fur_dual_ng_at((_e9 + (1u).xxx), g_6, l_6, p_1);
    float3 _e17 = fur_dual_at.w;
    return (_e6 + ((_e13 - _e6) * _e17));
}

float3 fur_rsqrt_newton(float3 v_1)
{
    float3 y_2 = (float3)0;

    y_2 = asfloat(((1597463174u).xxx - (asuint(v_1) >> (1u).xxx)));
    float3 h_4 = (0.5 * v_1);
    float3 _e12 = y_2;
    float3 _e13 = y_2;
    float3 _e15 = y_2;
    y_2 = (_e12 * ((1.5).xxx - ((h_4 * _e13) * _e15)));
    float3 _e21 = y_2;
    float3 _e22 = y_2;
    float3 _e24 = y_2;
    y_2 = (_e21 * ((1.5).xxx - ((h_4 * _e22) * _e24)));
    float3 _e30 = y_2;
    float3 _e31 = y_2;
    float3 _e33 = y_2;
    return (_e30 * ((1.5).xxx - ((h_4 * _e31) * _e33)));
}

float3 fur_exp_neg(float3 x_in)
{
    float3 p_2 = (0.00019875693).xxx;

    float3 x_19 = min(max(x_in, (0.0).xxx), (87.0).xxx);
    float3 k_21 = round((x_19 * FUR_LOG2_E));
    float3 r_16 = (((k_21 * FUR_LN2_HI) - x_19) + (k_21 * FUR_LN2_LO));
    float3 z_1 = (r_16 * r_16);
    float3 _e20 = p_2;
    p_2 = ((_e20 * r_16) + (0.0013981999).xxx);
    float3 _e25 = p_2;
    p_2 = ((_e25 * r_16) + (0.008333452).xxx);
    float3 _e30 = p_2;
    p_2 = ((_e30 * r_16) + (0.041665796).xxx);
    float3 _e35 = p_2;
    p_2 = ((_e35 * r_16) + (0.16666666).xxx);
    float3 _e40 = p_2;
    p_2 = ((_e40 * r_16) + (0.5).xxx);
    float3 _e45 = p_2;
    float3 e_1 = (((_e45 * z_1) + r_16) + (1.0).xxx);
    return ((x_in > (87.0).xxx) ? (0.0).xxx : ldexp(e_1, naga_neg(naga_f2i32(k_21))));
}

float3 fur_erf(float3 x_11)
{
    const bool3 _e7 = fur_is_nan3_(x_11);
    float3 a_11 = (_e7 ? (0.0).xxx : min(abs(x_11), (10.0).xxx));
    float3 p_6 = ((((((((((((FUR_ERF_A6_ * a_11) + (0.0002765672).xxx) * a_11) + (0.0001520143).xxx) * a_11) + (0.009270527).xxx) * a_11) + (0.04228201).xxx) * a_11) + (0.07052308).xxx) * a_11) + (1.0).xxx);
    float3 p2_ = (p_6 * p_6);
    float3 p4_ = (p2_ * p2_);
    float3 p8_ = (p4_ * p4_);
    float3 e_2 = ((1.0).xxx - ((1.0).xxx / (p8_ * p8_)));
    uint3 sign_ = (asuint(x_11) & (2147483648u).xxx);
    return asfloat((asuint(e_2) | sign_));
}

float3 fur_dual_between(float3 x_12, float3 top)
{
    const bool3 _e8 = fur_is_nan3_(x_12);
    return (_e8 ? (0.0).xxx : min(max(x_12, (0.0).xxx), top));
}

float3 fur_dual_gauss(float3 d_6, float3 v_in, float theta_i_5)
{
    float3 v_5 = clamp(v_in, (3e-6).xxx, (1e30).xxx);
    const float3 _e8 = fur_rsqrt_newton(v_5);
    float3 z_2 = (d_6 * _e8);
    const float3 _e13 = fur_exp_neg(((0.5 * z_2) * z_2));
    float3 g_8 = ((_e13 * _e8) * FUR_INV_SQRT_TAU);
    float3 centre = (((d_6 - (theta_i_5).xxx) * _e8) * FUR_FRAC_1_SQRT_2_);
    float3 half_range = ((FUR_HALF_PI * _e8) * FUR_FRAC_1_SQRT_2_);
    const float3 _e27 = fur_erf((centre + half_range));
    const float3 _e29 = fur_erf((centre - half_range));
    float3 mass_1 = (0.5 * (_e27 - _e29));
    return (g_8 / max(mass_1, (0.05).xxx));
}

float3 fur_dual_power(float3 log2_mu, float k_12)
{
    const float3 _e6 = fur_exp_neg(((-(k_12) * FUR_LN2_) * log2_mu));
    return _e6;
}

float3 fur_reflectance_squared(float3 mu, float3 t_9)
{
    float3 den_1 = (mu * ((1.0).xxx - (t_9 * mu)));
    const float3 _e14 = fur_dual_between(((mu - t_9) / max(den_1, (1e-6).xxx)), (1.0).xxx);
    return ((den_1 > (1e-6).xxx) ? _e14 : (0.0).xxx);
}

float3 fur_downward_flux(float3 mu_n, float3 mu_2m, float3 rho2_)
{
    float3 num = ((1.0).xxx - (rho2_ * mu_2m));
    float3 den_2 = ((1.0).xxx - (((rho2_ * mu_n) * mu_n) * mu_2m));
    float3 d_9 = (mu_n * (num / max(den_2, (1e-6).xxx)));
    const float3 _e18 = fur_dual_between(d_9, mu_n);
    return ((den_2 > (1e-6).xxx) ? _e18 : mu_n);
}

float3 fur_backscatter_factor(float3 rho2_1, float3 mu_1, float3 mu_2m_1)
{
    float3 tiny = (1e-6).xxx;
    float3 g_den = ((1.0).xxx - (rho2_1 * mu_2m_1));
    const float3 _e16 = fur_dual_between((((1.0).xxx - mu_2m_1) / max(g_den, tiny)), (1.0).xxx);
    return (((g_den > tiny) ? _e16 : (1.0).xxx) / max(mu_1, tiny));
}

float3 fur_dual_coat_node(uint3 n_1, uint k_13)
{
    const float3 _e3 = fur_dual_node(n_1, k_13, FUR_DUAL_LOG2_DECAY);
    const float3 _e5 = fur_dual_node(n_1, k_13, FUR_DUAL_A_F2_);
    float3 a_12 = clamp(_e5, (0.0).xxx, (1.0).xxx);
    const float3 _e12 = fur_dual_power(_e3, 1.0);
    const float3 _e16 = fur_rsqrt_newton(max(a_12, (1e-30).xxx));
    float3 t_16 = (a_12 * _e16);
    const float3 _e18 = fur_reflectance_squared(_e12, t_16);
    return _e18;
}

float3 fur_dual_coat(FurLoc l_7)
{
    uint3 lo_6 = fur_dual_at.node;
    const float3 _e5 = fur_dual_coat_node(lo_6, l_7.i);
    const float3 _e9 = fur_dual_coat_node(lo_6, (l_7.i + 1u));
    const float3 _e14 = fur_dual_coat_node((lo_6 + (1u).xxx), l_7.i);
    const float3 _e21 = fur_dual_coat_node((lo_6 + (1u).xxx), (l_7.i + 1u));
    float3 rho0_ = (_e5 + ((_e9 - _e5) * l_7.w));
    float3 rho1_ = (_e14 + ((_e21 - _e14) * l_7.w));
    float3 _e33 = fur_dual_at.w;
    return (rho0_ + ((rho1_ - rho0_) * _e33));
}

float fur_dual_clean(float x_13, float top_1)
{
    bool local_27 = (bool)0;

    const bool _e3 = fur_is_nan(x_13);
    if (!(_e3)) {
        local_27 = (x_13 > 0.0);
    } else {
        local_27 = false;
    }
    bool _e10 = local_27;
    return (_e10 ? min(x_13, top_1) : 0.0);
}

float fur_dual_below(float x_14)
{
    bool local_28 = (bool)0;

    const bool _e2 = fur_is_nan(x_14);
    float deep = (_e2 ? FUR_DUAL_MAX_FIBERS : 0.0);
    const bool _e9 = fur_is_nan(x_14);
    if (!(_e9)) {
        local_28 = (x_14 >= 0.0);
    } else {
        local_28 = false;
    }
    bool _e16 = local_28;
    return (_e16 ? min((x_14 + FUR_DUAL_LINE_SAMPLE_OFFSET), FUR_DUAL_MAX_FIBERS) : deep);
}

float fur_dual_below_at_incidence(float count_on_line, float cos_to_skin)
{
    bool local_29 = (bool)0;
    bool local_30 = (bool)0;
    bool local_31 = (bool)0;

    float skin_layers = ((FUR_DUAL_DIFFUSIVITY * min(abs(cos_to_skin), 1.0)) * (count_on_line + FUR_DUAL_LINE_SAMPLE_OFFSET));
    float as_count = max((skin_layers - FUR_DUAL_LINE_SAMPLE_OFFSET), 0.0);
    const bool _e14 = fur_is_nan(count_on_line);
    if (!(_e14)) {
        local_29 = (count_on_line >= 0.0);
    } else {
        local_29 = false;
    }
    bool _e21 = local_29;
    if (_e21) {
        local_30 = (count_on_line < FUR_DUAL_MAX_FIBERS);
    } else {
        local_30 = false;
    }
    bool _e27 = local_30;
    if (_e27) {
        const bool _e30 = fur_is_nan(cos_to_skin);
        local_31 = !(_e30);
    } else {
        local_31 = false;
    }
    bool known = local_31;
    return (known ? as_count : count_on_line);
}

float fur_dual_forward_density_at_incidence(float d_f, float cos_to_skin_1)
{
    float scaled = ((d_f * FUR_DUAL_DIFFUSIVITY) * min(abs(cos_to_skin_1), 1.0));
    const bool _e8 = fur_is_nan(cos_to_skin_1);
    return (_e8 ? d_f : scaled);
}

float3 fur_eval_dual(float theta_i_6, float theta_r_8, float phi_in_1, float fibers, float fibers_below, float d_f_in, float d_b_in, float3 sigma_ca_6)
{
    float3 out_4 = (float3)0;
    float p_3 = (float)0;
    float3 f_s = (float3)0;
    uint g_7 = 0u;

    const FurDualColour _e9 = fur_dual_locate(sigma_ca_6);
    fur_dual_at = _e9;
    float3 zero = (0.0).xxx;
    const bool _e12 = fur_valid(theta_i_6, theta_r_8, phi_in_1);
    if (!(_e12)) {
        return zero;
    }
    const float _e15 = fur_dual_clean(fibers, FUR_DUAL_MAX_FIBERS);
    const float _e16 = fur_dual_below(fibers_below);
    const float _e18 = fur_dual_clean(d_f_in, FUR_DUAL_MAX_DENSITY);
    const float _e20 = fur_dual_clean(d_b_in, FUR_DUAL_MAX_DENSITY);
    float x_20 = (theta_i_6 + theta_r_8);
    const float _e22 = fur_cos_within_half_pi(theta_i_6);
    float inv_cos2_1 = (1.0 / max((_e22 * _e22), FUR_MIN_COS2_));
    float direct = clamp((1.0 - _e15), 0.0, 1.0);
    const FurLoc _e33 = fur_dual_theta(theta_r_8);
    const float _e34 = fur_wrap_angle(phi_in_1);
    float abs_phi_2 = abs(_e34);
    const float3 _e41 = fur_dual_field(_e33, ((abs_phi_2 < FUR_HALF_PI) ? FUR_DUAL_BACK : FUR_DUAL_FRONT));
    const float3 _e43 = fur_dual_field(_e33, FUR_DUAL_LOG2_DECAY);
    const float3 _e45 = fur_dual_field(_e33, FUR_DUAL_A_F2_);
    const float3 _e47 = fur_dual_power(_e43, 1.0);
    const float3 _e50 = fur_dual_power(_e43, (2.0 * _e16));
    const float3 _e51 = fur_dual_coat(_e33);
    const float3 _e52 = fur_backscatter_factor(_e51, _e47, _e50);
    float3 half_energy = (_e41 * _e52);
    const float3 _e55 = fur_dual_field(_e33, FUR_DUAL_SIGMA_B0_);
    const float3 _e57 = fur_dual_field(_e33, FUR_DUAL_DELTA_B);
    float3 d_back = ((x_20).xxx - _e57);
    float3 s_b = (((1.0).xxx + (_e20 * _e45)) * _e55);
    float3 v_back = (s_b * s_b);
    float back_scale = ((_e20 * inv_cos2_1) / FUR_PI);
    out_4 = zero;
    if ((direct > 0.0)) {
        const float3 _e74 = fur_dual_gauss(d_back, v_back, theta_i_6);
        out_4 = (((direct * back_scale) * half_energy) * _e74);
    }
    if ((_e15 > 0.0)) {
        const FurLoc _e79 = fur_dual_theta(-(theta_i_6));
        const float3 _e81 = fur_dual_field(_e79, FUR_DUAL_LOG2_DECAY);
        const float3 _e83 = fur_dual_field(_e79, FUR_DUAL_BETA_F);
        const float3 _e84 = fur_dual_power(_e81, _e15);
        const float3 _e87 = fur_dual_power(_e81, (2.0 * _e16));
        const float3 _e88 = fur_dual_coat(_e79);
        const float3 _e89 = fur_downward_flux(_e84, _e87, _e88);
        float3 spread = (max((_e89 - (direct).xxx), zero) * _e18);
        if (any((spread > zero))) {
            float3 s2f = ((_e15 * _e83) * _e83);
            p_3 = (abs_phi_2 * FUR_DUAL_PHI_SCALE);
            float _e101 = p_3;
            float _e104 = p_3;
            p_3 = ((_e104 > 0.0) ? min(_e101, 31.0) : 0.0);
            float _e109 = p_3;
            uint j_7 = min(naga_f2u32(_e109), 30u);
            float _e113 = p_3;
            FurLoc at_phi = ConstructFurLoc(j_7, (_e113 - float(j_7)));
            f_s = zero;
            uint2 loop_bound_20 = uint2(4294967295u, 4294967295u);
            bool loop_init_19 = true;
            while(true) {
                if (all(loop_bound_20 == uint2(0u, 0u))) { break; }
                loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
                if (!loop_init_19) {
                    uint _e141 = g_7;
                    g_7 = (_e141 + 1u);
                }
                loop_init_19 = false;
                uint _e120 = g_7;
                if ((_e120 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e124 = g_7;
                    const float3 _e126 = fur_dual_field(_e33, (FUR_DUAL_MEAN + _e124));
                    uint _e128 = g_7;
                    const float3 _e130 = fur_dual_field(_e33, (FUR_DUAL_SD + _e128));
                    uint _e131 = g_7;
                    const float3 _e132 = fur_dual_ng(_e131, _e33, at_phi);
                    float3 v_6 = ((_e130 * _e130) + s2f);
                    float3 _e135 = f_s;
                    const float3 _e138 = fur_dual_gauss(((x_20).xxx - _e126), v_6, theta_i_6);
                    f_s = (_e135 + (_e132 * _e138));
                }
            }
            const float3 _e145 = fur_dual_gauss(d_back, (v_back + s2f), theta_i_6);
            float3 _e146 = out_4;
            float3 _e147 = f_s;
            out_4 = (_e146 + (spread * ((_e147 * inv_cos2_1) + ((back_scale * half_energy) * _e145))));
        }
    }
    float _e155 = out_4.x;
    const bool _e156 = fur_finite(_e155);
    float _e158 = out_4.y;
    const bool _e159 = fur_finite(_e158);
    float _e161 = out_4.z;
    const bool _e162 = fur_finite(_e161);
    bool3 finite = bool3(_e156, _e159, _e162);
    float3 _e164 = out_4;
    float3 _e165 = out_4;
    return ((finite & (_e165 > zero)) ? _e164 : zero);
}

float3 fur_eval_dual_dirs(float3 wi_2, float3 wr_2, float3 u_6, float fibers_1, float fibers_below_1, float d_f_1, float d_b, float3 sigma_ca_7)
{
    const FurDirAngles _e8 = fur_angles_from_dirs(wi_2, wr_2, u_6);
    if (!(_e8.ok)) {
        return (0.0).xxx;
    }
    const float3 _e16 = fur_eval_dual(_e8.theta_i, _e8.theta_r, _e8.phi, fibers_1, fibers_below_1, d_f_1, d_b, sigma_ca_7);
    return _e16;
}

float fur_coat_sigma_at(float x_15)
{
    float x2_1 = (x_15 * x_15);
    return clamp((x2_1 / max((1.0 - x2_1), 1e-12)), 0.0, FUR_SIGMA_CA_MAX);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

float fur_coat_sigma_for(float4 table[6], float c_2)
{
    float4 nodes_2[6] = (float4[6])0;
    uint k_14 = 0u;
    float t_10 = (float)0;

    nodes_2 = table;
    float _e5 = nodes_2[0].x;
    if ((c_2 >= _e5)) {
        return 0.0;
    }
    uint2 loop_bound_21 = uint2(4294967295u, 4294967295u);
    bool loop_init_20 = true;
    while(true) {
        if (all(loop_bound_21 == uint2(0u, 0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        if (!loop_init_20) {
            uint _e51 = k_14;
            k_14 = (_e51 + 1u);
        }
        loop_init_20 = false;
        uint _e10 = k_14;
        if ((_e10 < 23u)) {
        } else {
            break;
        }
        {
            uint _e13 = k_14;
            uint _e17 = k_14;
            float hi_4 = nodes_2[min(uint(naga_div(_e13, 4u)), 5u)][min(uint(naga_mod(_e17, 4u)), 3u)];
            uint _e22 = k_14;
            uint _e28 = k_14;
            float lo_7 = nodes_2[min(uint(naga_div((_e22 + 1u), 4u)), 5u)][min(uint(naga_mod((_e28 + 1u), 4u)), 3u)];
            if ((c_2 >= lo_7)) {
                t_10 = 0.0;
                if ((hi_4 > lo_7)) {
                    t_10 = ((hi_4 - c_2) / (hi_4 - lo_7));
                }
                uint _e42 = k_14;
                float _e44 = t_10;
                float x_21 = (((float(_e42) + _e44) / 23.0) * FUR_COAT_AXIS_END);
                const float _e50 = fur_coat_sigma_at(x_21);
                return _e50;
            }
        }
    }
    return FUR_SIGMA_CA_MAX;
}

float3 fur_absorption_from_colour(float4 table_1[6], float3 colour)
{
    const float _e3 = fur_coat_sigma_for(table_1, colour.x);
    const float _e5 = fur_coat_sigma_for(table_1, colour.y);
    const float _e7 = fur_coat_sigma_for(table_1, colour.z);
    return float3(_e3, _e5, _e7);
}

typedef float3 ret_Constructarray5_float3_[5];
ret_Constructarray5_float3_ Constructarray5_float3_(float3 arg0, float3 arg1, float3 arg2, float3 arg3, float3 arg4) {
    float3 ret[5] = { arg0, arg1, arg2, arg3, arg4 };
    return ret;
}

void fur_store(uint q, FurFamilies f_5)
{
    uint k_15 = 0u;

    uint base_1 = (16u * q);
    float3 parts[5] = Constructarray5_float3_(f_5.r, f_5.tt, f_5.trt, f_5.scattered, f_5.total);
    uint2 loop_bound_22 = uint2(4294967295u, 4294967295u);
    bool loop_init_21 = true;
    while(true) {
        if (all(loop_bound_22 == uint2(0u, 0u))) { break; }
        loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
        if (!loop_init_21) {
            uint _e46 = k_15;
            k_15 = (_e46 + 1u);
        }
        loop_init_21 = false;
        uint _e12 = k_15;
        if ((_e12 < 5u)) {
        } else {
            break;
        }
        {
            uint _e17 = k_15;
            uint _e21 = k_15;
            fur_results.Store((base_1 + (3u * _e17))*4, asuint(parts[min(uint(_e21), 4u)].x));
            uint _e26 = k_15;
            uint _e32 = k_15;
            fur_results.Store(((base_1 + (3u * _e26)) + 1u)*4, asuint(parts[min(uint(_e32), 4u)].y));
            uint _e37 = k_15;
            uint _e43 = k_15;
            fur_results.Store(((base_1 + (3u * _e37)) + 2u)*4, asuint(parts[min(uint(_e43), 4u)].z));
        }
    }
    fur_results.Store((base_1 + 15u)*4, asuint(0.0));
    return;
}

void fur_store_rgb(uint q_1, float3 v_2)
{
    uint k_16 = 3u;

    uint base_2 = (16u * q_1);
    fur_results.Store(base_2*4, asuint(v_2.x));
    fur_results.Store((base_2 + 1u)*4, asuint(v_2.y));
    fur_results.Store((base_2 + 2u)*4, asuint(v_2.z));
    uint2 loop_bound_23 = uint2(4294967295u, 4294967295u);
    bool loop_init_22 = true;
    while(true) {
        if (all(loop_bound_23 == uint2(0u, 0u))) { break; }
        loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
        if (!loop_init_22) {
            uint _e27 = k_16;
            k_16 = (_e27 + 1u);
        }
        loop_init_22 = false;
        uint _e19 = k_16;
        if ((_e19 < 16u)) {
        } else {
            break;
        }
        {
            uint _e23 = k_16;
            fur_results.Store((base_2 + _e23)*4, asuint(0.0));
        }
    }
    return;
}

uint NagaBufferLength(ByteAddressBuffer buffer)
{
    uint ret;
    buffer.GetDimensions(ret);
    return ret;
}

[numthreads(64, 1, 1)]
void fur_eval_main(uint3 id : SV_DispatchThreadID)
{
    uint q_2 = id.x;
    if ((((2u * q_2) + 1u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_13 = asfloat(fur_queries.Load4((2u * q_2)*16));
    float4 _e23 = asfloat(fur_queries.Load4(((2u * q_2) + 1u)*16));
    const FurFamilies _e25 = fur_eval_far(a_13.x, a_13.y, a_13.z, _e23.xyz);
    fur_store(q_2, _e25);
    return;
}

[numthreads(64, 1, 1)]
void fur_eval_dirs_main(uint3 id_1 : SV_DispatchThreadID)
{
    uint q_3 = id_1.x;
    if ((((3u * q_3) + 2u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 wi_3 = asfloat(fur_queries.Load4((3u * q_3)*16));
    float4 wr_3 = asfloat(fur_queries.Load4(((3u * q_3) + 1u)*16));
    float4 u_10 = asfloat(fur_queries.Load4(((3u * q_3) + 2u)*16));
    const FurFamilies _e35 = fur_eval_far_dirs(wi_3.xyz, wr_3.xyz, u_10.xyz, float3(wi_3.w, wr_3.w, u_10.w));
    fur_store(q_3, _e35);
    return;
}

[numthreads(64, 1, 1)]
void fur_sample_main(uint3 id_2 : SV_DispatchThreadID)
{
    uint q_4 = id_2.x;
    if ((((2u * q_4) + 1u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_14 = asfloat(fur_queries.Load4((2u * q_4)*16));
    float4 _e22 = asfloat(fur_queries.Load4(((2u * q_4) + 1u)*16));
    const FurSample _e24 = fur_sample_far(a_14.x, a_14.yzw, _e22.xyz);
    uint base_3 = (16u * q_4);
    fur_results.Store(base_3*4, asuint(_e24.theta_i));
    fur_results.Store((base_3 + 1u)*4, asuint(_e24.phi));
    fur_results.Store((base_3 + 2u)*4, asuint(_e24.pdf));
    fur_results.Store((base_3 + 3u)*4, asuint(_e24.weight.x));
    fur_results.Store((base_3 + 4u)*4, asuint(_e24.weight.y));
    fur_results.Store((base_3 + 5u)*4, asuint(_e24.weight.z));
    fur_results.Store((base_3 + 6u)*4, asuint(float(_e24.family)));
    fur_results.Store((base_3 + 7u)*4, asuint((_e24.ok ? 1.0 : 0.0)));
    return;
}

[numthreads(64, 1, 1)]
void fur_pdf_main(uint3 id_3 : SV_DispatchThreadID)
{
    uint q_5 = id_3.x;
    if ((((2u * q_5) + 1u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_15 = asfloat(fur_queries.Load4((2u * q_5)*16));
    float4 _e27 = asfloat(fur_queries.Load4(((2u * q_5) + 1u)*16));
    const float _e29 = fur_pdf_far(a_15.x, a_15.y, a_15.z, _e27.xyz);
    fur_results.Store((16u * q_5)*4, asuint(_e29));
    return;
}

[numthreads(64, 1, 1)]
void fur_dual_main(uint3 id_4 : SV_DispatchThreadID)
{
    uint q_6 = id_4.x;
    if ((((3u * q_6) + 2u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_16 = asfloat(fur_queries.Load4((3u * q_6)*16));
    float4 d_10 = asfloat(fur_queries.Load4(((3u * q_6) + 1u)*16));
    float4 sigma = asfloat(fur_queries.Load4(((3u * q_6) + 2u)*16));
    const float3 _e36 = fur_eval_dual(a_16.x, a_16.y, a_16.z, a_16.w, d_10.z, d_10.x, d_10.y, sigma.xyz);
    fur_store_rgb(q_6, _e36);
    return;
}

[numthreads(64, 1, 1)]
void fur_dual_dirs_main(uint3 id_5 : SV_DispatchThreadID)
{
    uint q_7 = id_5.x;
    if ((((4u * q_7) + 3u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 wi_4 = asfloat(fur_queries.Load4((4u * q_7)*16));
    float4 wr_4 = asfloat(fur_queries.Load4(((4u * q_7) + 1u)*16));
    float4 u_11 = asfloat(fur_queries.Load4(((4u * q_7) + 2u)*16));
    float4 below = asfloat(fur_queries.Load4(((4u * q_7) + 3u)*16));
    const float3 _e43 = fur_eval_dual_dirs(wi_4.xyz, wr_4.xyz, u_11.xyz, wi_4.w, below.x, wr_4.w, u_11.w, below.yzw);
    fur_store_rgb(q_7, _e43);
    return;
}

typedef float4 ret_Constructarray6_float4_[6];
ret_Constructarray6_float4_ Constructarray6_float4_(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5) {
    float4 ret[6] = { arg0, arg1, arg2, arg3, arg4, arg5 };
    return ret;
}

[numthreads(64, 1, 1)]
void fur_absorption_main(uint3 id_6 : SV_DispatchThreadID)
{
    uint q_8 = id_6.x;
    if (((6u + q_8) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 _e9 = asfloat(fur_queries.Load4(0));
    float4 _e12 = asfloat(fur_queries.Load4(16));
    float4 _e15 = asfloat(fur_queries.Load4(32));
    float4 _e18 = asfloat(fur_queries.Load4(48));
    float4 _e21 = asfloat(fur_queries.Load4(64));
    float4 _e24 = asfloat(fur_queries.Load4(80));
    float4 table_2[6] = Constructarray6_float4_(_e9, _e12, _e15, _e18, _e21, _e24);
    float4 _e30 = asfloat(fur_queries.Load4((6u + q_8)*16));
    const float3 _e32 = fur_absorption_from_colour(table_2, _e30.xyz);
    fur_store_rgb(q_8, _e32);
    return;
}
