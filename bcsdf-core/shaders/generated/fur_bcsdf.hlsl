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

struct FurLookups {
    float m[3];
    float ms[2];
    float n[12];
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
    uint first;
    uint channels;
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
    float3 mass;
    int _pad2_0;
    float3 lo;
    int _end_pad_0;
};

static const float FUR_PI = 3.1415927;
static const float FUR_HALF_PI = 1.5707964;
static const float FUR_TAU = 6.2831855;
static const float FUR_MIN_COS2_ = 0.0001;
static const uint FUR_HEADER_HALVES = 80u;
static const uint FUR_CLOSURE_WORD = 26u;

ByteAddressBuffer fur_lut : register(t0);
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
    float u_4 = min(max(((x * a.inv_step) + a.offset), 0.0), a.last);
    int i = min(naga_f2i32(u_4), asint(asuint(int(a.nodes)) - asuint(int(2))));
    const FurLoc furloc = ConstructFurLoc(uint(i), (u_4 - float(i)));
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
    const uint _e3 = fur_word((9u + t));
    return (asfloat(_e3) * asfloat(2004877312u));
}

float fur_cos_within_half_pi(float x_1)
{
    float acc = -2.755732e-7;
    float acc_1 = 2.7557319e-6;

    float a_3 = abs(x_1);
    if ((a_3 <= 0.7853982)) {
        float y_2 = (a_3 * a_3);
        float _e7 = acc;
        acc = ((_e7 * y_2) + 2.4801588e-5);
        float _e11 = acc;
        acc = ((_e11 * y_2) - 0.0013888889);
        float _e15 = acc;
        acc = ((_e15 * y_2) + 0.041666668);
        float _e19 = acc;
        acc = ((_e19 * y_2) - 0.5);
        float _e23 = acc;
        return ((_e23 * y_2) + 1.0);
    }
    float r_10 = ((1.5707964 - a_3) + -4.371139e-8);
    float y_3 = (r_10 * r_10);
    float _e34 = acc_1;
    acc_1 = ((_e34 * y_3) - 0.0001984127);
    float _e38 = acc_1;
    acc_1 = ((_e38 * y_3) + 0.008333334);
    float _e42 = acc_1;
    acc_1 = ((_e42 * y_3) - 0.16666667);
    float _e46 = acc_1;
    return (((_e46 * y_3) * r_10) + r_10);
}

float fur_wrap_angle(float x_2)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;
    float y = (float)0;
    bool local_3 = (bool)0;

    if ((x_2 > -3.1415927)) {
        local = (x_2 <= FUR_PI);
    } else {
        local = false;
    }
    bool _e8 = local;
    if (_e8) {
        return x_2;
    }
    if ((x_2 > FUR_PI)) {
        local_1 = (x_2 <= 9.424778);
    } else {
        local_1 = false;
    }
    bool _e16 = local_1;
    if (_e16) {
        return (x_2 - FUR_TAU);
    }
    if ((x_2 <= -3.1415927)) {
        local_2 = (x_2 > -9.424778);
    } else {
        local_2 = false;
    }
    bool _e26 = local_2;
    if (_e26) {
        return (x_2 + FUR_TAU);
    }
    y = (x_2 - (FUR_TAU * floor(((x_2 + FUR_PI) / FUR_TAU))));
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

bool fur_finite(float x_3)
{
    return ((asuint(x_3) & 2139095040u) != 2139095040u);
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

FurDensity ConstructFurDensity(uint arg0, uint arg1, uint arg2, uint arg3, float arg4, uint arg5, uint arg6, uint arg7, uint arg8) {
    FurDensity ret = (FurDensity)0;
    ret.prefix_at = arg0;
    ret.entries = arg1;
    ret.nodes = arg2;
    ret.rows = arg3;
    ret.step_ = arg4;
    ret.block = arg5;
    ret.table = arg6;
    ret.first = arg7;
    ret.channels = arg8;
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
    uint values = (((3u * _e2) + ((12u * _e6) * _e4)) + ((2u * _e8) * _e10));
    at = (160u + (2u * values));
    const uint _e27 = fur_entries(_e2, 1u);
    const uint _e29 = fur_entries(_e6, 8u);
    const uint _e31 = fur_entries(_e8, 8u);
    if ((d < 3u)) {
        uint _e34 = at;
        const FurDensity furdensity = ConstructFurDensity((_e34 + ((4u * d) * _e27)), _e27, _e2, 1u, (6.2831855 / float((_e2 - 1u))), 1u, 0u, d, 1u);
        return furdensity;
    }
    uint _e49 = at;
    at = (_e49 + (12u * _e27));
    if ((d < 7u)) {
        uint f_2 = (d - 3u);
        uint _e57 = at;
        const FurDensity furdensity_1 = ConstructFurDensity((_e57 + (((4u * f_2) * _e4) * _e29)), _e29, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, (3u * f_2), 3u);
        return furdensity_1;
    }
    uint _e74 = at;
    at = (_e74 + ((16u * _e4) * _e29));
    if ((d < 9u)) {
        uint x_8 = (d - 7u);
        uint _e83 = at;
        const FurDensity furdensity_2 = ConstructFurDensity((_e83 + (((4u * x_8) * _e10) * _e31)), _e31, _e8, _e10, (FUR_PI / float((_e8 - 1u))), 8u, 2u, x_8, 1u);
        return furdensity_2;
    }
    uint _e98 = at;
    at = (_e98 + ((8u * _e10) * _e31));
    uint _e103 = at;
    const FurDensity furdensity_3 = ConstructFurDensity(_e103, _e29, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, 9u, 3u);
    return furdensity_3;
}

uint fur_norm_start()
{
    const FurDensity _e1 = fur_density(9u);
    return (_e1.prefix_at + ((4u * _e1.rows) * _e1.entries));
}

float fur_f32_at(uint byte)
{
    uint w_3 = (byte >> 2u);
    if (((byte & 3u) == 0u)) {
        uint _e9 = asuint(fur_lut.Load(w_3*4));
        return asfloat(_e9);
    }
    uint _e13 = asuint(fur_lut.Load(w_3*4));
    uint _e20 = asuint(fur_lut.Load((w_3 + 1u)*4));
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

FurLookups ConstructFurLookups(float arg0[3], float arg1[2], float arg2[12], float arg3, float arg4) {
    FurLookups ret = (FurLookups)0;
    ret.m = arg0;
    ret.ms = arg1;
    ret.n = arg2;
    ret.front = arg3;
    ret.inv_cos2_ = arg4;
    return ret;
}

FurLookups fur_lookups(float theta_i_1, float theta_r_2, float phi_in)
{
    float m[3] = (float[3])0;
    uint ch = 0u;
    uint ch_1 = 0u;
    float ms[2] = (float[2])0;
    uint ch_2 = 0u;
    float n[12] = (float[12])0;
    uint ch_3 = 0u;

    const float _e3 = fur_wrap_angle(phi_in);
    const uint _e5 = fur_word(4u);
    const uint _e7 = fur_word(5u);
    const uint _e9 = fur_word(6u);
    const uint _e11 = fur_word(7u);
    const uint _e13 = fur_word(8u);
    uint n0_ = (FUR_HEADER_HALVES + (3u * _e5));
    uint s0_ = (n0_ + ((12u * _e9) * _e7));
    float abs_phi = abs(_e3);
    const float _e23 = fur_cos_within_half_pi(theta_i_1);
    float inv_cos2_ = (1.0 / max((_e23 * _e23), FUR_MIN_COS2_));
    const FurAxis _e31 = fur_axis(true, 0.15915494, _e5);
    const FurLoc _e33 = fur_locate(_e31, (theta_i_1 + theta_r_2));
    const float _e35 = fur_unbias(0u);
    float wm0_ = ((1.0 - _e33.w) * _e35);
    float wm1_ = (_e33.w * _e35);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e69 = ch;
            ch = (_e69 + 1u);
        }
        loop_init_1 = false;
        uint _e45 = ch;
        if ((_e45 < 3u)) {
        } else {
            break;
        }
        {
            uint _e52 = ch;
            const float _e54 = fur_half(((FUR_HEADER_HALVES + (3u * _e33.i)) + _e52));
            uint _e61 = ch;
            const float _e63 = fur_half(((FUR_HEADER_HALVES + (3u * (_e33.i + 1u))) + _e61));
            uint _e64 = ch;
            m[min(uint(_e64), 2u)] = ((wm0_ * _e54) + (wm1_ * _e63));
        }
    }
    const float3 _e72 = fur_sphere_norms(theta_r_2);
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e86 = ch_1;
            ch_1 = (_e86 + 1u);
        }
        loop_init_2 = false;
        uint _e75 = ch_1;
        if ((_e75 < 3u)) {
        } else {
            break;
        }
        {
            uint _e78 = ch_1;
            uint _e80 = ch_1;
            float _e82 = m[min(uint(_e80), 2u)];
            uint _e83 = ch_1;
            m[min(uint(_e78), 2u)] = (_e82 * _e72[min(uint(_e83), 2u)]);
        }
    }
    const FurAxis _e91 = fur_axis(true, 0.31830987, _e13);
    const FurLoc _e92 = fur_locate(_e91, theta_r_2);
    const FurAxis _e95 = fur_axis(true, 0.31830987, _e11);
    const FurLoc _e96 = fur_locate(_e95, theta_i_1);
    const float _e98 = fur_unbias(2u);
    {
        float ky0_ = ((1.0 - _e92.w) * _e98);
        float ky1_ = (_e92.w * _e98);
        float w0_ = (ky0_ * (1.0 - _e96.w));
        float w1_ = (ky0_ * _e96.w);
        float w2_ = (ky1_ * (1.0 - _e96.w));
        float w3_ = (ky1_ * _e96.w);
        uint i0_ = ((_e92.i * _e11) + _e96.i);
        uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
        bool loop_init_3 = true;
        while(true) {
            if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init_3) {
                uint _e166 = ch_2;
                ch_2 = (_e166 + 1u);
            }
            loop_init_3 = false;
            uint _e124 = ch_2;
            if ((_e124 < 2u)) {
            } else {
                break;
            }
            {
                uint _e130 = ch_2;
                const float _e132 = fur_half(((s0_ + (2u * i0_)) + _e130));
                uint _e138 = ch_2;
                const float _e140 = fur_half(((s0_ + (2u * (i0_ + 1u))) + _e138));
                uint _e145 = ch_2;
                const float _e147 = fur_half(((s0_ + (2u * (i0_ + _e11))) + _e145));
                uint _e154 = ch_2;
                const float _e156 = fur_half(((s0_ + (2u * ((i0_ + _e11) + 1u))) + _e154));
                uint _e157 = ch_2;
                ms[min(uint(_e157), 1u)] = ((((w0_ * _e132) + (w1_ * _e140)) + (w2_ * _e147)) + (w3_ * _e156));
            }
        }
    }
    float front_w = min((abs_phi * 0.31830987), 1.0);
    const FurAxis _e175 = fur_axis(false, 0.63661975, _e7);
    const FurLoc _e177 = fur_locate(_e175, abs(theta_r_2));
    const FurAxis _e180 = fur_axis(false, 0.31830987, _e9);
    const FurLoc _e181 = fur_locate(_e180, abs_phi);
    const float _e183 = fur_unbias(1u);
    float ny0_ = ((1.0 - _e177.w) * _e183);
    float ny1_ = (_e177.w * _e183);
    float v0_6 = (ny0_ * (1.0 - _e181.w));
    float v1_6 = (ny0_ * _e181.w);
    float v2_ = (ny1_ * (1.0 - _e181.w));
    float v3_ = (ny1_ * _e181.w);
    uint j0_ = ((_e177.i * _e9) + _e181.i);
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e251 = ch_3;
            ch_3 = (_e251 + 1u);
        }
        loop_init_4 = false;
        uint _e209 = ch_3;
        if ((_e209 < 12u)) {
        } else {
            break;
        }
        {
            uint _e215 = ch_3;
            const float _e217 = fur_half(((n0_ + (12u * j0_)) + _e215));
            uint _e223 = ch_3;
            const float _e225 = fur_half(((n0_ + (12u * (j0_ + 1u))) + _e223));
            uint _e230 = ch_3;
            const float _e232 = fur_half(((n0_ + (12u * (j0_ + _e9))) + _e230));
            uint _e239 = ch_3;
            const float _e241 = fur_half(((n0_ + (12u * ((j0_ + _e9) + 1u))) + _e239));
            uint _e242 = ch_3;
            n[min(uint(_e242), 11u)] = ((((v0_6 * _e217) + (v1_6 * _e225)) + (v2_ * _e232)) + (v3_ * _e241));
        }
    }
    float _e254[3] = m;
    float _e255[2] = ms;
    float _e256[12] = n;
    const FurLookups furlookups = ConstructFurLookups(_e254, _e255, _e256, front_w, inv_cos2_);
    return furlookups;
}

typedef float ret_Constructarray4_float_[4];
ret_Constructarray4_float_ Constructarray4_float_(float arg0, float arg1, float arg2, float arg3) {
    float ret[4] = { arg0, arg1, arg2, arg3 };
    return ret;
}

FurFamilies fur_assemble(FurLookups l)
{
    float3 f[4] = (float3[4])0;
    uint k_1 = 0u;

    float mss = (l.ms[0] + (l.front * (l.ms[1] - l.ms[0])));
    float lon[4] = Constructarray4_float_(l.m[0], l.m[1], l.m[2], mss);
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_5 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_5) {
            uint _e51 = k_1;
            k_1 = (_e51 + 1u);
        }
        loop_init_5 = false;
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
            f[min(uint(_e28), 3u)] = (float3(l.n[min(uint((3u * _e32)), 11u)], l.n[min(uint(((3u * _e37) + 1u)), 11u)], l.n[min(uint(((3u * _e44) + 2u)), 11u)]) * weight);
        }
    }
    float3 _e55 = f[0];
    float3 _e57 = f[1];
    float3 _e59 = f[2];
    float3 _e61 = f[3];
    float3 _e63 = f[0];
    float3 _e65 = f[1];
    float3 _e68 = f[2];
    float3 _e71 = f[3];
    const FurFamilies furfamilies_1 = ConstructFurFamilies(_e55, _e57, _e59, _e61, (((_e63 + _e65) + _e68) + _e71));
    return furfamilies_1;
}

FurFamilies fur_eval_far(float theta_i_2, float theta_r_3, float phi_1)
{
    const bool _e3 = fur_valid(theta_i_2, theta_r_3, phi_1);
    if (!(_e3)) {
        const FurFamilies _e5 = fur_zero();
        const FurFamilies furfamilies_2 = _e5;
        return furfamilies_2;
    }
    const FurLookups _e6 = fur_lookups(theta_i_2, theta_r_3, phi_1);
    const FurFamilies _e7 = fur_assemble(_e6);
    const FurFamilies furfamilies_3 = _e7;
    return furfamilies_3;
}

float fur_asin(float x_4)
{
    float ax = min(abs(x_4), 1.0);
    float x2_ = (ax * ax);
    float x4_ = (x2_ * x2_);
    float p01_ = ((-0.001262491 * ax) + 0.00667009);
    float p23_ = ((-0.017088126 * ax) + 0.03089188);
    float p45_ = ((-0.050174303 * ax) + 0.08897899);
    float p67_ = ((-0.2145988 * ax) + FUR_HALF_PI);
    float poly = ((((p01_ * x2_) + p23_) * x4_) + ((p45_ * x2_) + p67_));
    float r_11 = (FUR_HALF_PI - (sqrt((1.0 - ax)) * poly));
    return (((asuint(x_4) & 2147483648u) != 0u) ? -(abs(r_11)) : abs(r_11));
}

float fur_atan_poly(float t_1)
{
    float t2_ = (t_1 * t_1);
    float t4_ = (t2_ * t2_);
    float p01_1 = ((0.0029202348 * t_1) + -0.016366187);
    float p23_1 = ((0.043209206 * t_1) + -0.07552008);
    float p45_1 = ((0.10665919 * t_1) + -0.14211038);
    float p67_1 = ((0.19993772 * t_1) + -0.33333153);
    return ((((p01_1 * t2_) + p23_1) * t4_) + ((p45_1 * t2_) + p67_1));
}

float fur_atan2_(float y_1, float x_5)
{
    float r = (float)0;

    float ax_1 = abs(x_5);
    float ay = abs(y_1);
    float a_4 = (min(ax_1, ay) / max(max(ax_1, ay), 1.1754944e-38));
    float t_6 = (a_4 * a_4);
    const float _e10 = fur_atan_poly(t_6);
    r = (a_4 + (a_4 * (t_6 * _e10)));
    float _e15 = r;
    float _e17 = r;
    r = ((ay > ax_1) ? (FUR_HALF_PI - _e17) : _e15);
    float _e21 = r;
    float _e23 = r;
    r = ((x_5 < 0.0) ? (FUR_PI - _e23) : _e21);
    float _e28 = r;
    float _e29 = r;
    return (((asuint(y_1) & 2147483648u) != 0u) ? -(_e29) : _e28);
}

FurFamilies fur_eval_far_dirs(float3 wi, float3 wr, float3 u)
{
    bool local_8 = (bool)0;
    bool local_9 = (bool)0;
    bool local_10 = (bool)0;
    bool local_11 = (bool)0;

    float ii = dot(wi, wi);
    float rr = dot(wr, wr);
    float uu = dot(u, u);
    const bool _e6 = fur_finite(ii);
    if (_e6) {
        const bool _e9 = fur_finite(rr);
        local_8 = _e9;
    } else {
        local_8 = false;
    }
    bool _e11 = local_8;
    if (_e11) {
        const bool _e14 = fur_finite(uu);
        local_9 = _e14;
    } else {
        local_9 = false;
    }
    bool _e16 = local_9;
    if (!(_e16)) {
        const FurFamilies _e18 = fur_zero();
        const FurFamilies furfamilies_4 = _e18;
        return furfamilies_4;
    }
    float ni = sqrt(ii);
    float nr = sqrt(rr);
    float nu = sqrt(uu);
    if (!((ni < 1.1754944e-38))) {
        local_10 = (nr < 1.1754944e-38);
    } else {
        local_10 = true;
    }
    bool _e29 = local_10;
    if (!(_e29)) {
        local_11 = (nu < 1.1754944e-38);
    } else {
        local_11 = true;
    }
    bool _e35 = local_11;
    if (_e35) {
        const FurFamilies _e36 = fur_zero();
        const FurFamilies furfamilies_5 = _e36;
        return furfamilies_5;
    }
    float3 un = (u * (1.0 / nu));
    float a_5 = dot(wi, un);
    float b_2 = dot(wr, un);
    const float _e48 = fur_asin(clamp((a_5 * (1.0 / ni)), -1.0, 1.0));
    const float _e55 = fur_asin(clamp((b_2 * (1.0 / nr)), -1.0, 1.0));
    float y_4 = dot(un, cross(wi, wr));
    float x_9 = (dot(wi, wr) - (a_5 * b_2));
    const float _e61 = fur_atan2_(y_4, x_9);
    const FurFamilies _e63 = fur_eval_far(_e48, _e55, abs(_e61));
    const FurFamilies furfamilies_6 = _e63;
    return furfamilies_6;
}

typedef uint ret_Constructarray3_uint_[3];
ret_Constructarray3_uint_ Constructarray3_uint_(uint arg0, uint arg1, uint arg2) {
    uint ret[3] = { arg0, arg1, arg2 };
    return ret;
}

float fur_node(FurDensity d_1, uint row, uint j)
{
    const uint _e4 = fur_word(4u);
    const uint _e6 = fur_word(5u);
    const uint _e8 = fur_word(6u);
    uint n0_1 = (FUR_HEADER_HALVES + (3u * _e4));
    uint s0_1 = (n0_1 + ((12u * _e8) * _e6));
    uint starts[3] = Constructarray3_uint_(FUR_HEADER_HALVES, n0_1, s0_1);
    uint chans[3] = Constructarray3_uint_(3u, 12u, 2u);
    uint base = ((starts[min(uint(d_1.table), 2u)] + (((row * d_1.nodes) + j) * chans[min(uint(d_1.table), 2u)])) + d_1.first);
    if ((d_1.channels == 3u)) {
        const float _e36 = fur_half(base);
        const float _e39 = fur_half((base + 1u));
        const float _e43 = fur_half((base + 2u));
        float sum = ((_e36 + _e39) + _e43);
        const float _e46 = fur_unbias(d_1.table);
        return (sum * (_e46 * 0.33333334));
    }
    const float _e50 = fur_half(base);
    const float _e52 = fur_unbias(d_1.table);
    return (_e50 * _e52);
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
    float x_6 = 0.5;
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
        x_6 = _e43;
    }
    uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
    bool loop_init_6 = true;
    while(true) {
        if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
        if (!loop_init_6) {
            uint _e102 = k_4;
            k_4 = (_e102 + 1u);
        }
        loop_init_6 = false;
        uint _e50 = k_4;
        if ((_e50 < 8u)) {
        } else {
            break;
        }
        {
            float _e53 = x_6;
            float _e54 = x_6;
            float _e57 = x_6;
            float fx = ((_e53 * (q0_ + (_e54 * ((0.5 * cb) + ((_e57 * 0.33333334) * cc))))) - goal);
            if ((fx > 0.0)) {
                float _e68 = x_6;
                hi = _e68;
            } else {
                float _e69 = x_6;
                lo = _e69;
            }
            float _e70 = x_6;
            float _e71 = x_6;
            float d_5 = (q0_ + (_e70 * (cb + (_e71 * cc))));
            float _e76 = lo;
            float _e77 = hi;
            next = (0.5 * (_e76 + _e77));
            if ((d_5 > 0.0)) {
                float _e84 = x_6;
                float n_1 = (_e84 - (fx / d_5));
                float _e87 = lo;
                if ((n_1 >= _e87)) {
                    float _e91 = hi;
                    local_15 = (n_1 <= _e91);
                } else {
                    local_15 = false;
                }
                bool _e94 = local_15;
                if (_e94) {
                    next = n_1;
                }
            }
            float _e95 = next;
            float _e96 = x_6;
            bool done = (abs((_e95 - _e96)) <= 1.2e-7);
            float _e101 = next;
            x_6 = _e101;
            if (done) {
                break;
            }
        }
    }
    float _e105 = x_6;
    float s_1 = clamp((_e105 * len_3), 0.0, len_3);
    float inset_1 = (len_3 * 9.536743e-7);
    if ((q0_ <= 0.0)) {
        local_16 = (s_1 < inset_1);
    } else {
        local_16 = false;
    }
    bool _e117 = local_16;
    if (_e117) {
        return inset_1;
    }
    if ((q1_ <= 0.0)) {
        local_17 = (s_1 > (len_3 - inset_1));
    } else {
        local_17 = false;
    }
    bool _e125 = local_17;
    if (_e125) {
        return (len_3 - inset_1);
    }
    return s_1;
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

float fur_unit(float u_1)
{
    if ((u_1 > 0.0)) {
        return min(u_1, 0.99999994);
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
    uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        uint _e9 = len_4;
        if ((_e9 <= 1u)) {
            break;
        }
        uint _e12 = len_4;
        uint half_ = naga_div(_e12, 2u);
        uint _e15 = lo_1;
        uint _e16 = lo_1;
        uint _e18 = lo_1;
        const float _e20 = fur_rows_prefix(r_8, (_e18 + half_));
        lo_1 = ((_e20 < t_5) ? (_e16 + half_) : _e15);
        uint _e23 = len_4;
        len_4 = (_e23 - half_);
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
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e85 = j_5;
            j_5 = (_e85 + 1u);
        }
        loop_init_7 = false;
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

float fur_rows_invert_between(FurRows r_9, float t0_, float t1_, float u_2)
{
    float inset_2 = ((t1_ - t0_) * 9.536743e-7);
    const float _e7 = fur_unit(u_2);
    float t_7 = clamp((t0_ + (_e7 * (t1_ - t0_))), (t0_ + inset_2), (t1_ - inset_2));
    const float _e14 = fur_rows_invert(r_9, t_7);
    return _e14;
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
    FurMAt out_1 = ConstructFurMAt((0.0).xxx, (0.0).xxx);
    uint g_1 = 0u;

    const FurDensity _e2 = fur_density(0u);
    float off = (l_1.w * _e2.step_);
    uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e45 = g_1;
            g_1 = (_e45 + 1u);
        }
        loop_init_8 = false;
        uint _e14 = g_1;
        if ((_e14 < 3u)) {
        } else {
            break;
        }
        {
            uint _e17 = g_1;
            const FurDensity _e18 = fur_density(_e17);
            const float _e21 = fur_node(_e18, 0u, l_1.i);
            const float _e26 = fur_node(_e18, 0u, (l_1.i + 1u));
            float at_2 = (_e21 + ((_e26 - _e21) * l_1.w));
            uint _e32 = g_1;
            const float _e39 = fur_f32_at((_e18.prefix_at + (4u * l_1.i)));
            const float _e40 = fur_linear_mass(_e21, at_2, off);
            out_1.cdf[min(uint(_e32), 2u)] = (_e39 + _e40);
            uint _e43 = g_1;
            out_1.value[min(uint(_e43), 2u)] = at_2;
        }
    }
    FurMAt _e48 = out_1;
    const FurMAt furmat = _e48;
    return furmat;
}

float3 fur_m_cdf(float x_7)
{
    const FurAxis _e1 = fur_sum_axis();
    const FurLoc _e2 = fur_locate(_e1, x_7);
    const FurMAt _e3 = fur_m_at(_e2);
    return _e3.cdf;
}

float fur_row_total(FurDensity d_4, FurLoc l_2)
{
    const float _e17 = fur_f32_at((d_4.prefix_at + (4u * (((min(l_2.i, (d_4.rows - 1u)) * d_4.entries) + d_4.entries) - 1u))));
    const float _e35 = fur_f32_at((d_4.prefix_at + (4u * (((min((l_2.i + 1u), (d_4.rows - 1u)) * d_4.entries) + d_4.entries) - 1u))));
    return (_e17 + ((_e35 - _e17) * l_2.w));
}

float fur_positive(float v)
{
    bool local_18 = (bool)0;

    const bool _e1 = fur_finite(v);
    if (_e1) {
        local_18 = (v > 0.0);
    } else {
        local_18 = false;
    }
    bool _e7 = local_18;
    return (_e7 ? v : 0.0);
}

typedef float ret_Constructarray5_float_[5];
ret_Constructarray5_float_ Constructarray5_float_(float arg0, float arg1, float arg2, float arg3, float arg4) {
    float ret[5] = { arg0, arg1, arg2, arg3, arg4 };
    return ret;
}

FurParts ConstructFurParts(float arg0[5], float3 arg1, float3 arg2) {
    FurParts ret = (FurParts)0;
    ret.a = arg0;
    ret.mass = arg1;
    ret.lo = arg2;
    return ret;
}

FurParts fur_parts(float theta_r_4)
{
    const float3 _e3 = fur_m_cdf((theta_r_4 - FUR_HALF_PI));
    const float3 _e6 = fur_m_cdf((theta_r_4 + FUR_HALF_PI));
    float3 mass = max((_e6 - _e3), (0.0).xxx);
    const uint _e14 = fur_word(5u);
    const FurAxis _e15 = fur_axis(false, 0.63661975, _e14);
    const FurLoc _e17 = fur_locate(_e15, abs(theta_r_4));
    const uint _e21 = fur_word(8u);
    const FurAxis _e22 = fur_axis(true, 0.31830987, _e21);
    const FurLoc _e23 = fur_locate(_e22, theta_r_4);
    const FurDensity _e25 = fur_density(6u);
    const float _e26 = fur_row_total(_e25, _e17);
    const FurDensity _e28 = fur_density(9u);
    const float _e29 = fur_row_total(_e28, _e17);
    const float3 _e30 = fur_sphere_norms(theta_r_4);
    float3 kept = (mass * _e30);
    const FurDensity _e36 = fur_density(3u);
    const float _e37 = fur_row_total(_e36, _e17);
    const float _e39 = fur_positive(((2.0 * kept.x) * _e37));
    const FurDensity _e44 = fur_density(4u);
    const float _e45 = fur_row_total(_e44, _e17);
    const float _e47 = fur_positive(((2.0 * kept.y) * _e45));
    const FurDensity _e52 = fur_density(5u);
    const float _e53 = fur_row_total(_e52, _e17);
    const float _e55 = fur_positive(((2.0 * kept.z) * _e53));
    const FurDensity _e57 = fur_density(7u);
    const float _e58 = fur_row_total(_e57, _e23);
    const float _e63 = fur_positive(((2.0 * _e58) * (_e26 - _e29)));
    const FurDensity _e65 = fur_density(8u);
    const float _e66 = fur_row_total(_e65, _e23);
    const float _e70 = fur_positive(((2.0 * _e66) * _e29));
    float a_6[5] = Constructarray5_float_(_e39, _e47, _e55, _e63, _e70);
    const FurParts furparts = ConstructFurParts(a_6, mass, _e3);
    return furparts;
}

float fur_density_of(FurLookups l_3, float w_2, float cos_theta_i)
{
    if (!((w_2 > 0.0))) {
        return 0.0;
    }
    float mean0_ = (((l_3.n[0] + l_3.n[1]) + l_3.n[2]) * 0.33333334);
    float mean1_ = (((l_3.n[3] + l_3.n[4]) + l_3.n[5]) * 0.33333334);
    float mean2_ = (((l_3.n[6] + l_3.n[7]) + l_3.n[8]) * 0.33333334);
    float mean3_ = (((l_3.n[9] + l_3.n[10]) + l_3.n[11]) * 0.33333334);
    float ms_1 = (l_3.ms[0] + (l_3.front * (l_3.ms[1] - l_3.ms[0])));
    float p = ((((l_3.m[0] * mean0_) + (l_3.m[1] * mean1_)) + (l_3.m[2] * mean2_)) + (ms_1 * mean3_));
    const float _e74 = fur_positive(((p / w_2) / max(cos_theta_i, 1e-6)));
    return _e74;
}

float fur_pdf_far(float theta_i_3, float theta_r_5, float phi_2)
{
    const bool _e3 = fur_valid(theta_i_3, theta_r_5, phi_2);
    if (!(_e3)) {
        return 0.0;
    }
    const FurParts _e6 = fur_parts(theta_r_5);
    float w_4 = ((((_e6.a[0] + _e6.a[1]) + _e6.a[2]) + _e6.a[3]) + _e6.a[4]);
    const FurLookups _e21 = fur_lookups(theta_i_3, theta_r_5, phi_2);
    const float _e22 = fur_cos_within_half_pi(theta_i_3);
    const float _e23 = fur_density_of(_e21, w_4, _e22);
    return _e23;
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

FurSample fur_sample_far(float theta_r_6, float3 u_3)
{
    FurSample out_2 = ConstructFurSample(0.0, 0.0, 0.0, (0.0).xxx, 0u, false);
    bool local_19 = (bool)0;
    float total = 0.0;
    uint k_5 = 0u;
    float acc_3 = 0.0;
    uint c = 5u;
    float u0_ = 0.0;
    uint last = 5u;
    uint k_6 = 0u;
    float theta_i_4 = 0.0;
    FurRows nrows = (FurRows)0;
    bool local_20 = (bool)0;

    const bool _e11 = fur_finite(theta_r_6);
    if (_e11) {
        local_19 = (abs(theta_r_6) <= FUR_HALF_PI);
    } else {
        local_19 = false;
    }
    bool _e18 = local_19;
    if (!(_e18)) {
        FurSample _e20 = out_2;
        const FurSample fursample = _e20;
        return fursample;
    }
    const FurParts _e21 = fur_parts(theta_r_6);
    uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e34 = k_5;
            k_5 = (_e34 + 1u);
        }
        loop_init_9 = false;
        uint _e26 = k_5;
        if ((_e26 < 5u)) {
        } else {
            break;
        }
        {
            float _e29 = total;
            uint _e31 = k_5;
            total = (_e29 + _e21.a[min(uint(_e31), 4u)]);
        }
    }
    float _e37 = total;
    if (!((_e37 > 0.0))) {
        FurSample _e41 = out_2;
        const FurSample fursample_1 = _e41;
        return fursample_1;
    }
    const float _e43 = fur_unit(u_3.x);
    float _e44 = total;
    float target_mass = (_e43 * _e44);
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_10 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_10) {
            uint _e76 = k_6;
            k_6 = (_e76 + 1u);
        }
        loop_init_10 = false;
        uint _e56 = k_6;
        if ((_e56 < 5u)) {
        } else {
            break;
        }
        {
            uint _e60 = k_6;
            float wk = _e21.a[min(uint(_e60), 4u)];
            if (!((wk > 0.0))) {
                continue;
            }
            uint _e65 = k_6;
            last = _e65;
            float _e66 = acc_3;
            if ((target_mass < (_e66 + wk))) {
                uint _e69 = k_6;
                c = _e69;
                float _e70 = acc_3;
                const float _e73 = fur_unit(((target_mass - _e70) / wk));
                u0_ = _e73;
                break;
            }
            float _e74 = acc_3;
            acc_3 = (_e74 + wk);
        }
    }
    uint _e79 = c;
    if ((_e79 == 5u)) {
        uint _e82 = last;
        c = _e82;
        u0_ = 0.99999994;
    }
    float total_weight = ((((_e21.a[0] + _e21.a[1]) + _e21.a[2]) + _e21.a[3]) + _e21.a[4]);
    float _e98 = u0_;
    bool negative = (_e98 < 0.5);
    uint _e103 = c;
    if ((_e103 < 3u)) {
        uint _e106 = c;
        const FurDensity _e107 = fur_density(_e106);
        const FurRows _e111 = fur_rows(_e107, 0u, 0.0, -3.1415927);
        uint _e113 = c;
        uint _e116 = c;
        uint _e119 = c;
        const float _e123 = fur_rows_invert_between(_e111, _e21.lo[min(uint(_e113), 2u)], (_e21.lo[min(uint(_e116), 2u)] + _e21.mass[min(uint(_e119), 2u)]), u_3.y);
        theta_i_4 = clamp((_e123 - theta_r_6), -1.5707964, FUR_HALF_PI);
    } else {
        const uint _e131 = fur_word(8u);
        const FurAxis _e132 = fur_axis(true, 0.31830987, _e131);
        const FurLoc _e133 = fur_locate(_e132, theta_r_6);
        uint _e135 = c;
        const FurDensity _e139 = fur_density(((7u + _e135) - 3u));
        const FurRows _e143 = fur_rows(_e139, _e133.i, _e133.w, -1.5707964);
        const float _e145 = fur_rows_total(_e143);
        const float _e147 = fur_rows_invert_between(_e143, 0.0, _e145, u_3.y);
        theta_i_4 = clamp(_e147, -1.5707964, FUR_HALF_PI);
    }
    uint _e151 = c;
    uint family = min(_e151, 3u);
    const uint _e157 = fur_word(5u);
    const FurAxis _e158 = fur_axis(false, 0.63661975, _e157);
    const FurLoc _e160 = fur_locate(_e158, abs(theta_r_6));
    const FurDensity _e163 = fur_density((3u + family));
    const FurRows _e167 = fur_rows(_e163, _e160.i, _e160.w, 0.0);
    nrows = _e167;
    uint _e169 = c;
    if ((_e169 >= 3u)) {
        uint _e172 = c;
        const FurRows _e177 = fur_rows_weighted((_e172 - 2u), _e160.i, _e160.w);
        nrows = _e177;
    }
    FurRows _e178 = nrows;
    FurRows _e180 = nrows;
    const float _e181 = fur_rows_total(_e180);
    const float _e183 = fur_rows_invert_between(_e178, 0.0, _e181, u_3.z);
    float abs_phi_1 = clamp(_e183, 0.0, FUR_PI);
    const float _e189 = fur_wrap_angle((negative ? -(abs_phi_1) : abs_phi_1));
    float _e190 = theta_i_4;
    const FurLookups _e191 = fur_lookups(_e190, theta_r_6, _e189);
    float _e192 = theta_i_4;
    const float _e193 = fur_cos_within_half_pi(_e192);
    const float _e194 = fur_density_of(_e191, total_weight, _e193);
    if ((_e194 > 0.0)) {
        const bool _e199 = fur_finite(_e194);
        local_20 = _e199;
    } else {
        local_20 = false;
    }
    bool _e201 = local_20;
    if (!(_e201)) {
        FurSample _e203 = out_2;
        const FurSample fursample_2 = _e203;
        return fursample_2;
    }
    const FurFamilies _e204 = fur_assemble(_e191);
    float _e205 = theta_i_4;
    float k_8 = (max(cos(_e205), 0.0) / _e194);
    float _e210 = theta_i_4;
    out_2 = ConstructFurSample(_e210, _e189, _e194, max((_e204.total * k_8), (0.0).xxx), family, true);
    FurSample _e218 = out_2;
    const FurSample fursample_3 = _e218;
    return fursample_3;
}

typedef float3 ret_Constructarray5_float3_[5];
ret_Constructarray5_float3_ Constructarray5_float3_(float3 arg0, float3 arg1, float3 arg2, float3 arg3, float3 arg4) {
    float3 ret[5] = { arg0, arg1, arg2, arg3, arg4 };
    return ret;
}

void fur_store(uint q, FurFamilies f_1)
{
    uint k_7 = 0u;

    uint base_1 = (16u * q);
    float3 parts[5] = Constructarray5_float3_(f_1.r, f_1.tt, f_1.trt, f_1.scattered, f_1.total);
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e46 = k_7;
            k_7 = (_e46 + 1u);
        }
        loop_init_11 = false;
        uint _e12 = k_7;
        if ((_e12 < 5u)) {
        } else {
            break;
        }
        {
            uint _e17 = k_7;
            uint _e21 = k_7;
            fur_results.Store((base_1 + (3u * _e17))*4, asuint(parts[min(uint(_e21), 4u)].x));
            uint _e26 = k_7;
            uint _e32 = k_7;
            fur_results.Store(((base_1 + (3u * _e26)) + 1u)*4, asuint(parts[min(uint(_e32), 4u)].y));
            uint _e37 = k_7;
            uint _e43 = k_7;
            fur_results.Store(((base_1 + (3u * _e37)) + 2u)*4, asuint(parts[min(uint(_e43), 4u)].z));
        }
    }
    fur_results.Store((base_1 + 15u)*4, asuint(0.0));
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
    uint q_1 = id.x;
    if ((q_1 >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_7 = asfloat(fur_queries.Load4(q_1*16));
    const FurFamilies _e11 = fur_eval_far(a_7.x, a_7.y, a_7.z);
    fur_store(q_1, _e11);
    return;
}

[numthreads(64, 1, 1)]
void fur_eval_dirs_main(uint3 id_1 : SV_DispatchThreadID)
{
    uint q_2 = id_1.x;
    if ((((3u * q_2) + 2u) >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 _e13 = asfloat(fur_queries.Load4((3u * q_2)*16));
    float4 _e21 = asfloat(fur_queries.Load4(((3u * q_2) + 1u)*16));
    float4 _e29 = asfloat(fur_queries.Load4(((3u * q_2) + 2u)*16));
    const FurFamilies _e31 = fur_eval_far_dirs(_e13.xyz, _e21.xyz, _e29.xyz);
    fur_store(q_2, _e31);
    return;
}

[numthreads(64, 1, 1)]
void fur_sample_main(uint3 id_2 : SV_DispatchThreadID)
{
    uint q_3 = id_2.x;
    if ((q_3 >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_8 = asfloat(fur_queries.Load4(q_3*16));
    const FurSample _e10 = fur_sample_far(a_8.x, a_8.yzw);
    uint base_2 = (16u * q_3);
    fur_results.Store(base_2*4, asuint(_e10.theta_i));
    fur_results.Store((base_2 + 1u)*4, asuint(_e10.phi));
    fur_results.Store((base_2 + 2u)*4, asuint(_e10.pdf));
    fur_results.Store((base_2 + 3u)*4, asuint(_e10.weight.x));
    fur_results.Store((base_2 + 4u)*4, asuint(_e10.weight.y));
    fur_results.Store((base_2 + 5u)*4, asuint(_e10.weight.z));
    fur_results.Store((base_2 + 6u)*4, asuint(float(_e10.family)));
    fur_results.Store((base_2 + 7u)*4, asuint((_e10.ok ? 1.0 : 0.0)));
    return;
}

[numthreads(64, 1, 1)]
void fur_pdf_main(uint3 id_3 : SV_DispatchThreadID)
{
    uint q_4 = id_3.x;
    if ((q_4 >= ((NagaBufferLength(fur_queries) - 0) / 16))) {
        return;
    }
    float4 a_9 = asfloat(fur_queries.Load4(q_4*16));
    const float _e15 = fur_pdf_far(a_9.x, a_9.y, a_9.z);
    fur_results.Store((16u * q_4)*4, asuint(_e15));
    return;
}
