#version 310 es

precision highp float;
precision highp int;

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct FurFamilies {
    vec3 r;
    vec3 tt;
    vec3 trt;
    vec3 scattered;
    vec3 total;
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
    uvec3 plane;
    vec3 w0_;
    vec3 w1_;
    vec3 w2_;
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
    vec3 weight;
    uint family;
    bool ok;
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
    vec4 s;
};
struct FurMAt {
    vec3 cdf;
    vec3 value;
};
struct FurParts {
    float a[5];
    FurRange ranges[5];
};
struct FurDualColour {
    uvec3 node;
    vec3 w;
};
const float FUR_PI = 3.1415927;
const float FUR_HALF_PI = 1.5707964;
const float FUR_TAU = 6.2831855;
const float FUR_MIN_COS2_ = 0.0001;
const float FUR_POLE_SLIVER = 0.010000167;
const uint FUR_HEADER_HALVES = 84u;
const uint FUR_N_ABS_WORD = 9u;
const uint FUR_SCALE_WORD = 10u;
const uint FUR_ABS_SCALE_WORD = 39u;
const float FUR_SIGMA_CA_MAX = 1000.0;
const float FUR_ROOT_RATE = 8.325476;
const float FUR_ROOT_SHARE = 0.4;
const float FUR_LOG2_E = 1.442695;
const uint FUR_CLOSURE_WORD = 27u;
const uint FUR_DUAL_HEADER_WORDS = 20u;
const uint FUR_DUAL_ABS_NODES = 16u;
const uint FUR_DUAL_NODE_HALVES = 9152u;
const float FUR_DUAL_KNEE = 3.0;
const float FUR_DUAL_SIGMA_MAX = 1000.0;
const uint FUR_DUAL_FIELDS = 15u;
const uint FUR_DUAL_LOG2_DECAY = 0u;
const uint FUR_DUAL_BETA_F = 1u;
const uint FUR_DUAL_BACK = 2u;
const uint FUR_DUAL_FRONT = 3u;
const uint FUR_DUAL_DELTA_B = 4u;
const uint FUR_DUAL_SIGMA_B0_ = 5u;
const uint FUR_DUAL_A_F2_ = 6u;
const uint FUR_DUAL_MEAN = 7u;
const uint FUR_DUAL_SD = 11u;
const uint FUR_DUAL_THETA_NODES = 64u;
const uint FUR_DUAL_PHI_NODES = 32u;
const uint FUR_DUAL_NG_START = 960u;
const float FUR_DUAL_THETA_SCALE = 20.371832;
const float FUR_DUAL_PHI_SCALE = 9.867606;
const float FUR_DUAL_MAX_FIBERS = 1000000.0;
const float FUR_DUAL_MAX_DENSITY = 4.0;
const float FUR_DUAL_MIN_VARIANCE = 3e-6;
const float FUR_DUAL_LINE_SAMPLE_OFFSET = 1.0;
const float FUR_DUAL_MIN_MASS = 0.05;
const float FUR_DUAL_TINY = 1e-6;
const float FUR_LN2_ = 0.6931472;
const float FUR_LN2_HI = 0.6933594;
const float FUR_LN2_LO = -0.00021219444;
const float FUR_INV_SQRT_TAU = 0.3989423;
const float FUR_FRAC_1_SQRT_2_ = 0.70710677;
const float FUR_ERF_A1_ = 0.07052308;
const float FUR_ERF_A2_ = 0.04228201;
const float FUR_ERF_A3_ = 0.009270527;
const float FUR_ERF_A4_ = 0.0001520143;
const float FUR_ERF_A5_ = 0.0002765672;
const float FUR_ERF_A6_ = 4.30638e-5;
const float FUR_DUAL_DIFFUSIVITY = 2.0;
const uint FUR_COAT_NODES = 24u;
const float FUR_COAT_AXIS_END = 0.9995004;

layout(std430) readonly buffer type_1_block_0Compute { uint _group_0_binding_0_cs[]; };

layout(std430) readonly buffer type_20_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) buffer type_21_block_2Compute { float _group_0_binding_2_cs[]; };


FurAxis fur_axis(bool centred, float inv_span, uint nodes) {
    float last_1 = float((nodes - 1u));
    return FurAxis((last_1 * inv_span), (centred ? (0.5 * last_1) : 0.0), last_1, nodes);
}

FurLoc fur_locate(FurAxis a, float x) {
    float u_7 = min(max(((x * a.inv_step) + a.offset), 0.0), a.last);
    int i_1 = min(int(u_7), (int(a.nodes) - 2));
    return FurLoc(uint(i_1), (u_7 - float(i_1)));
}

uint fur_word(uint k) {
    uint _e3 = _group_0_binding_0_cs[k];
    return _e3;
}

float fur_half(uint h) {
    uint word = _group_0_binding_0_cs[(h >> 1u)];
    uint bits = (((h & 1u) == 1u) ? (word >> 16u) : (word & 65535u));
    return uintBitsToFloat((bits << 13u));
}

float fur_unbias(uint t) {
    uint _e3 = fur_word((FUR_SCALE_WORD + t));
    return (uintBitsToFloat(_e3) * uintBitsToFloat(2004877312u));
}

uint fur_n_plane_halves() {
    uint _e2 = fur_word(6u);
    uint _e5 = fur_word(5u);
    return ((4u * _e2) * _e5);
}

bvec3 fur_is_nan3_(vec3 x_1) {
    return greaterThan((floatBitsToUint(x_1) & uvec3(2147483647u)), uvec3(2139095040u));
}

vec3 fur_pow2_neg(vec3 y_in) {
    bvec3 _e9 = fur_is_nan3_(y_in);
    vec3 y_3 = mix(min(max(y_in, vec3(0.0)), vec3(125.0)), vec3(0.0), _e9);
    vec3 k_17 = roundEven(y_3);
    vec3 f_6 = (k_17 - y_3);
    vec3 f2_ = (f_6 * f_6);
    vec3 f4_ = (f2_ * f2_);
    vec3 p01_ = ((1.5252734e-5 * f_6) + vec3(0.0001540353));
    vec3 p23_ = ((0.0013333558 * f_6) + vec3(0.009618129));
    vec3 p45_ = ((0.05550411 * f_6) + vec3(0.2402265));
    vec3 p67_ = ((0.6931472 * f_6) + vec3(1.0));
    vec3 p_4 = ((((p01_ * f2_) + p23_) * f4_) + ((p45_ * f2_) + p67_));
    return ldexp(p_4, -(ivec3(k_17)));
}

FurColour fur_locate_colour(vec3 sigma_ca) {
    uint _e2 = fur_word(FUR_N_ABS_WORD);
    float last_2 = float((_e2 - 1u));
    uint _e7 = fur_word(FUR_ABS_SCALE_WORD);
    float scale = uintBitsToFloat(_e7);
    bvec3 _e17 = fur_is_nan3_(sigma_ca);
    vec3 s_1 = mix(min(max(sigma_ca, vec3(0.0)), vec3(1000.0)), vec3(0.0), _e17);
    vec3 _e23 = fur_pow2_neg(sqrt((s_1 * FUR_ROOT_RATE)));
    vec3 _e30 = fur_pow2_neg(((s_1 / vec3(scale)) * FUR_LOG2_E));
    vec3 e = ((FUR_ROOT_SHARE * _e23) + (0.6 * _e30));
    vec3 x_16 = min((vec3(1.0) - e), vec3(1.0));
    vec3 u_8 = clamp((x_16 * last_2), vec3(0.0), vec3(last_2));
    uvec3 k_18 = min(uvec3(u_8), uvec3((_e2 - 3u)));
    vec3 t_11 = (u_8 - vec3(k_18));
    vec3 w0_ = ((0.5 * (t_11 - vec3(1.0))) * (t_11 - vec3(2.0)));
    vec3 w1_ = (t_11 * (vec3(2.0) - t_11));
    vec3 w2_ = ((0.5 * t_11) * (t_11 - vec3(1.0)));
    uint _e71 = fur_word(6u);
    uint _e73 = fur_word(5u);
    return FurColour((k_18 * (_e71 * _e73)), w0_, w1_, w2_);
}

float fur_cos_within_half_pi(float x_2) {
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

float fur_wrap_angle(float x_3) {
    bool local = false;
    bool local_1 = false;
    bool local_2 = false;
    float y = 0.0;
    bool local_3 = false;
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

FurFamilies fur_zero() {
    vec3 z = vec3(0.0);
    return FurFamilies(z, z, z, z, z);
}

bool fur_finite(float x_4) {
    return ((floatBitsToUint(x_4) & 2139095040u) != 2139095040u);
}

bool fur_valid(float theta_i, float theta_r, float phi) {
    bool local_4 = false;
    bool local_5 = false;
    bool local_6 = false;
    bool local_7 = false;
    bool _e3 = fur_finite(theta_i);
    if (_e3) {
        bool _e6 = fur_finite(theta_r);
        local_4 = _e6;
    } else {
        local_4 = false;
    }
    bool _e8 = local_4;
    if (_e8) {
        bool _e11 = fur_finite(phi);
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

uint fur_entries(uint nodes_1, uint block) {
    return (((((nodes_1 - 1u) + block) - 1u) / block) + 1u);
}

FurDensity fur_density(uint d) {
    uint at = 0u;
    uint _e2 = fur_word(4u);
    uint _e4 = fur_word(5u);
    uint _e6 = fur_word(6u);
    uint _e8 = fur_word(7u);
    uint _e10 = fur_word(8u);
    uint _e13 = fur_n_plane_halves();
    uint _e15 = fur_word(FUR_N_ABS_WORD);
    uint values = (((3u * _e2) + (_e13 * _e15)) + ((2u * _e8) * _e10));
    at = (168u + (2u * values));
    uint _e28 = fur_entries(_e2, 1u);
    uint _e30 = fur_entries(_e6, 8u);
    uint _e32 = fur_entries(_e8, 8u);
    if ((d < 3u)) {
        uint _e35 = at;
        return FurDensity((_e35 + ((4u * d) * _e28)), _e28, _e2, 1u, (6.2831855 / float((_e2 - 1u))), 1u, 0u, d);
    }
    uint _e49 = at;
    at = (_e49 + (12u * _e28));
    if ((d < 7u)) {
        uint f_7 = (d - 3u);
        uint _e57 = at;
        return FurDensity((_e57 + (((4u * f_7) * _e4) * _e30)), _e30, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, f_7);
    }
    uint _e71 = at;
    at = (_e71 + ((16u * _e4) * _e30));
    if ((d < 9u)) {
        uint x_17 = (d - 7u);
        uint _e80 = at;
        return FurDensity((_e80 + (((4u * x_17) * _e10) * _e32)), _e32, _e8, _e10, (FUR_PI / float((_e8 - 1u))), 8u, 2u, x_17);
    }
    uint _e94 = at;
    at = (_e94 + ((8u * _e10) * _e32));
    uint _e99 = at;
    return FurDensity(_e99, _e30, _e6, _e4, (FUR_PI / float((_e6 - 1u))), 8u, 1u, 3u);
}

uint fur_norm_start() {
    FurDensity _e1 = fur_density(9u);
    return (_e1.prefix_at + ((4u * _e1.rows) * _e1.entries));
}

float fur_f32_at(uint byte) {
    uint w_4 = (byte >> 2u);
    if (((byte & 3u) == 0u)) {
        uint _e9 = _group_0_binding_0_cs[w_4];
        return uintBitsToFloat(_e9);
    }
    uint _e13 = _group_0_binding_0_cs[w_4];
    uint _e20 = _group_0_binding_0_cs[(w_4 + 1u)];
    return uintBitsToFloat(((_e13 >> 16u) | (_e20 << 16u)));
}

vec3 fur_sphere_norms(float theta_r_1) {
    vec3 out_ = vec3(0.0);
    uint g = 0u;
    uint _e2 = fur_word(FUR_CLOSURE_WORD);
    if ((_e2 != 1u)) {
        return vec3(1.0);
    }
    uint _e10 = fur_word(4u);
    FurAxis _e11 = fur_axis(true, 0.31830987, _e10);
    FurLoc _e12 = fur_locate(_e11, theta_r_1);
    uint _e13 = fur_norm_start();
    uint at_1 = (_e13 + (12u * _e12.i));
    bool loop_init = true;
    while(true) {
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
            float _e30 = fur_f32_at((at_1 + (4u * _e27)));
            uint _e31 = g;
            uint _e36 = g;
            float _e39 = fur_f32_at(((at_1 + 12u) + (4u * _e36)));
            out_[_e31] = (_e30 + ((_e39 - _e30) * _e12.w));
        }
    }
    vec3 _e47 = out_;
    return _e47;
}

FurLookups fur_lookups(float theta_i_1, float theta_r_2, float phi_in, vec3 sigma_ca_1) {
    float m[3] = float[3](0.0, 0.0, 0.0);
    uint ch = 0u;
    uint ch_1 = 0u;
    float ms[2] = float[2](0.0, 0.0);
    uint ch_2 = 0u;
    float n[12] = float[12](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint c = 0u;
    uint f = 0u;
    float left = 0.0;
    float right = 0.0;
    uint i = 0u;
    float nl[4] = float[4](0.0, 0.0, 0.0, 0.0);
    uint f_1 = 0u;
    float _e4 = fur_wrap_angle(phi_in);
    uint _e6 = fur_word(4u);
    uint _e8 = fur_word(5u);
    uint _e10 = fur_word(6u);
    uint _e12 = fur_word(7u);
    uint _e14 = fur_word(8u);
    uint n0_ = (FUR_HEADER_HALVES + (3u * _e6));
    uint _e19 = fur_n_plane_halves();
    uint _e21 = fur_word(FUR_N_ABS_WORD);
    uint s0_ = (n0_ + (_e19 * _e21));
    float abs_phi = abs(_e4);
    float _e25 = fur_cos_within_half_pi(theta_i_1);
    float inv_cos2_ = (1.0 / max((_e25 * _e25), FUR_MIN_COS2_));
    FurAxis _e33 = fur_axis(true, 0.15915494, _e6);
    FurLoc _e35 = fur_locate(_e33, (theta_i_1 + theta_r_2));
    float _e37 = fur_unbias(0u);
    float wm0_ = ((1.0 - _e35.w) * _e37);
    float wm1_ = (_e35.w * _e37);
    bool loop_init_1 = true;
    while(true) {
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
            float _e56 = fur_half(((FUR_HEADER_HALVES + (3u * _e35.i)) + _e54));
            uint _e63 = ch;
            float _e65 = fur_half(((FUR_HEADER_HALVES + (3u * (_e35.i + 1u))) + _e63));
            uint _e66 = ch;
            m[_e66] = ((wm0_ * _e56) + (wm1_ * _e65));
        }
    }
    vec3 _e74 = fur_sphere_norms(theta_r_2);
    bool loop_init_2 = true;
    while(true) {
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
            float _e84 = m[_e82];
            uint _e85 = ch_1;
            m[_e80] = (_e84 * _e74[_e85]);
        }
    }
    FurAxis _e93 = fur_axis(true, 0.31830987, _e14);
    FurLoc _e94 = fur_locate(_e93, theta_r_2);
    FurAxis _e97 = fur_axis(true, 0.31830987, _e12);
    FurLoc _e98 = fur_locate(_e97, theta_i_1);
    float _e100 = fur_unbias(2u);
    {
        float ky0_ = ((1.0 - _e94.w) * _e100);
        float ky1_ = (_e94.w * _e100);
        float w0_1 = (ky0_ * (1.0 - _e98.w));
        float w1_1 = (ky0_ * _e98.w);
        float w2_1 = (ky1_ * (1.0 - _e98.w));
        float w3_ = (ky1_ * _e98.w);
        uint i0_ = ((_e94.i * _e12) + _e98.i);
        bool loop_init_3 = true;
        while(true) {
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
                float _e134 = fur_half(((s0_ + (2u * i0_)) + _e132));
                uint _e140 = ch_2;
                float _e142 = fur_half(((s0_ + (2u * (i0_ + 1u))) + _e140));
                uint _e147 = ch_2;
                float _e149 = fur_half(((s0_ + (2u * (i0_ + _e12))) + _e147));
                uint _e156 = ch_2;
                float _e158 = fur_half(((s0_ + (2u * ((i0_ + _e12) + 1u))) + _e156));
                uint _e159 = ch_2;
                ms[_e159] = ((((w0_1 * _e134) + (w1_1 * _e142)) + (w2_1 * _e149)) + (w3_ * _e158));
            }
        }
    }
    float front_w = min((abs_phi * 0.31830987), 1.0);
    FurAxis _e177 = fur_axis(false, 0.63661975, _e8);
    FurLoc _e179 = fur_locate(_e177, abs(theta_r_2));
    FurAxis _e182 = fur_axis(false, 0.31830987, _e10);
    FurLoc _e183 = fur_locate(_e182, abs_phi);
    float _e185 = fur_unbias(1u);
    float ny0_ = ((1.0 - _e179.w) * _e185);
    float ny1_ = (_e179.w * _e185);
    float v0_8 = (ny0_ * (1.0 - _e183.w));
    float v1_8 = (ny0_ * _e183.w);
    float v2_ = (ny1_ * (1.0 - _e183.w));
    float v3_ = (ny1_ * _e183.w);
    uint j0_ = ((_e179.i * _e10) + _e183.i);
    FurColour _e208 = fur_locate_colour(sigma_ca_1);
    uint _e209 = fur_n_plane_halves();
    bool loop_init_4 = true;
    while(true) {
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
            vec3 tw = vec3(_e208.w0_[_e217], _e208.w1_[_e220], _e208.w2_[_e223]);
            float l_8[6] = float[6]((tw.x * v0_8), (tw.x * v2_), (tw.y * v0_8), (tw.y * v2_), (tw.z * v0_8), (tw.z * v2_));
            float r_14[6] = float[6]((tw.x * v1_8), (tw.x * v3_), (tw.y * v1_8), (tw.y * v3_), (tw.z * v1_8), (tw.z * v3_));
            uint _e254 = c;
            uint h_3 = (n0_ + (4u * (_e208.plane[_e254] + j0_)));
            uint rows[6] = uint[6](h_3, (h_3 + (4u * _e10)), (h_3 + _e209), ((h_3 + _e209) + (4u * _e10)), (h_3 + (2u * _e209)), ((h_3 + (2u * _e209)) + (4u * _e10)));
            f = 0u;
            bool loop_init_5 = true;
            while(true) {
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
                    float _e285 = fur_half((rows[0] + _e283));
                    left = (_e285 * l_8[0]);
                    uint _e292 = f;
                    float _e294 = fur_half(((rows[0] + 4u) + _e292));
                    right = (_e294 * r_14[0]);
                    i = 1u;
                    bool loop_init_6 = true;
                    while(true) {
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
                            float _e308 = fur_half((rows[_e304] + _e306));
                            uint _e309 = i;
                            left = (_e303 + (_e308 * l_8[_e309]));
                            float _e313 = right;
                            uint _e314 = i;
                            uint _e318 = f;
                            float _e320 = fur_half(((rows[_e314] + 4u) + _e318));
                            uint _e321 = i;
                            right = (_e313 + (_e320 * r_14[_e321]));
                        }
                    }
                    uint _e329 = f;
                    uint _e331 = c;
                    float _e334 = left;
                    float _e335 = right;
                    n[((3u * _e329) + _e331)] = max((_e334 + _e335), 0.0);
                }
            }
        }
    }
    bool loop_init_7 = true;
    while(true) {
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
            float _e356 = fur_half(((n0_ + (4u * j0_)) + _e354));
            uint _e362 = f_1;
            float _e364 = fur_half(((n0_ + (4u * (j0_ + 1u))) + _e362));
            uint _e369 = f_1;
            float _e371 = fur_half(((n0_ + (4u * (j0_ + _e10))) + _e369));
            uint _e378 = f_1;
            float _e380 = fur_half(((n0_ + (4u * ((j0_ + _e10) + 1u))) + _e378));
            uint _e381 = f_1;
            nl[_e381] = ((((v0_8 * _e356) + (v1_8 * _e364)) + (v2_ * _e371)) + (v3_ * _e380));
        }
    }
    float _e393[3] = m;
    float _e394[2] = ms;
    float _e395[12] = n;
    float _e396[4] = nl;
    return FurLookups(_e393, _e394, _e395, _e396, front_w, inv_cos2_);
}

FurFamilies fur_assemble(FurLookups l) {
    vec3 f_2[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint k_1 = 0u;
    float mss = (l.ms[0] + (l.front * (l.ms[1] - l.ms[0])));
    float lon[4] = float[4](l.m[0], l.m[1], l.m[2], mss);
    bool loop_init_8 = true;
    while(true) {
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
            float weight = (lon[_e24] * l.inv_cos2_);
            uint _e28 = k_1;
            uint _e32 = k_1;
            uint _e37 = k_1;
            uint _e44 = k_1;
            f_2[_e28] = (vec3(l.n[(3u * _e32)], l.n[((3u * _e37) + 1u)], l.n[((3u * _e44) + 2u)]) * weight);
        }
    }
    vec3 _e55 = f_2[0];
    vec3 _e57 = f_2[1];
    vec3 _e59 = f_2[2];
    vec3 _e61 = f_2[3];
    vec3 _e63 = f_2[0];
    vec3 _e65 = f_2[1];
    vec3 _e68 = f_2[2];
    vec3 _e71 = f_2[3];
    return FurFamilies(_e55, _e57, _e59, _e61, (((_e63 + _e65) + _e68) + _e71));
}

FurFamilies fur_eval_far(float theta_i_2, float theta_r_3, float phi_1, vec3 sigma_ca_2) {
    bool _e4 = fur_valid(theta_i_2, theta_r_3, phi_1);
    if (!(_e4)) {
        FurFamilies _e6 = fur_zero();
        return _e6;
    }
    FurLookups _e7 = fur_lookups(theta_i_2, theta_r_3, phi_1, sigma_ca_2);
    FurFamilies _e8 = fur_assemble(_e7);
    return _e8;
}

float fur_asin(float x_5) {
    float ax_3 = min(abs(x_5), 1.0);
    float x2_ = (ax_3 * ax_3);
    float x4_ = (x2_ * x2_);
    float p01_1 = ((-0.001262491 * ax_3) + 0.00667009);
    float p23_1 = ((-0.017088126 * ax_3) + 0.03089188);
    float p45_1 = ((-0.050174303 * ax_3) + 0.08897899);
    float p67_1 = ((-0.2145988 * ax_3) + FUR_HALF_PI);
    float poly = ((((p01_1 * x2_) + p23_1) * x4_) + ((p45_1 * x2_) + p67_1));
    float r_15 = (FUR_HALF_PI - (sqrt((1.0 - ax_3)) * poly));
    return (((floatBitsToUint(x_5) & 2147483648u) != 0u) ? -(abs(r_15)) : abs(r_15));
}

float fur_atan_poly(float t_1) {
    float t2_ = (t_1 * t_1);
    float t4_ = (t2_ * t2_);
    float p01_2 = ((0.0029202348 * t_1) + -0.016366187);
    float p23_2 = ((0.043209206 * t_1) + -0.07552008);
    float p45_2 = ((0.10665919 * t_1) + -0.14211038);
    float p67_2 = ((0.19993772 * t_1) + -0.33333153);
    return ((((p01_2 * t2_) + p23_2) * t4_) + ((p45_2 * t2_) + p67_2));
}

float fur_atan2_(float y_1, float x_6) {
    float r = 0.0;
    float ax_4 = abs(x_6);
    float ay = abs(y_1);
    float a_8 = (min(ax_4, ay) / max(max(ax_4, ay), 1.1754944e-38));
    float t_12 = (a_8 * a_8);
    float _e10 = fur_atan_poly(t_12);
    r = (a_8 + (a_8 * (t_12 * _e10)));
    float _e15 = r;
    float _e17 = r;
    r = ((ay > ax_4) ? (FUR_HALF_PI - _e17) : _e15);
    float _e21 = r;
    float _e23 = r;
    r = ((x_6 < 0.0) ? (FUR_PI - _e23) : _e21);
    float _e28 = r;
    float _e29 = r;
    return (((floatBitsToUint(y_1) & 2147483648u) != 0u) ? -(_e29) : _e28);
}

FurDirAngles fur_angles_from_dirs(vec3 wi, vec3 wr, vec3 u) {
    bool local_8 = false;
    bool local_9 = false;
    bool local_10 = false;
    bool local_11 = false;
    FurDirAngles none = FurDirAngles(0.0, 0.0, 0.0, false);
    float ii = dot(wi, wi);
    float rr = dot(wr, wr);
    float uu = dot(u, u);
    bool _e11 = fur_finite(ii);
    if (_e11) {
        bool _e14 = fur_finite(rr);
        local_8 = _e14;
    } else {
        local_8 = false;
    }
    bool _e16 = local_8;
    if (_e16) {
        bool _e19 = fur_finite(uu);
        local_9 = _e19;
    } else {
        local_9 = false;
    }
    bool _e21 = local_9;
    if (!(_e21)) {
        return none;
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
        return none;
    }
    vec3 un = (u * (1.0 / nu));
    float a_9 = dot(wi, un);
    float b_3 = dot(wr, un);
    float _e51 = fur_asin(clamp((a_9 * (1.0 / ni)), -1.0, 1.0));
    float _e58 = fur_asin(clamp((b_3 * (1.0 / nr)), -1.0, 1.0));
    float y_6 = dot(un, cross(wi, wr));
    float x_18 = (dot(wi, wr) - (a_9 * b_3));
    float _e64 = fur_atan2_(y_6, x_18);
    return FurDirAngles(_e51, _e58, abs(_e64), true);
}

FurFamilies fur_eval_far_dirs(vec3 wi_1, vec3 wr_1, vec3 u_1, vec3 sigma_ca_3) {
    FurDirAngles _e4 = fur_angles_from_dirs(wi_1, wr_1, u_1);
    if (!(_e4.ok)) {
        FurFamilies _e7 = fur_zero();
        return _e7;
    }
    FurFamilies _e11 = fur_eval_far(_e4.theta_i, _e4.theta_r, _e4.phi, sigma_ca_3);
    return _e11;
}

float fur_node(FurDensity d_1, uint row, uint j) {
    uint _e6 = fur_word(4u);
    uint n0_1 = (FUR_HEADER_HALVES + (3u * _e6));
    uint _e9 = fur_n_plane_halves();
    uint _e11 = fur_word(FUR_N_ABS_WORD);
    uint s0_1 = (n0_1 + (_e9 * _e11));
    uint starts[3] = uint[3](FUR_HEADER_HALVES, n0_1, s0_1);
    uint chans[3] = uint[3](3u, 4u, 2u);
    uint base = ((starts[d_1.table] + (((row * d_1.nodes) + j) * chans[d_1.table])) + d_1.channel);
    float _e30 = fur_half(base);
    float _e32 = fur_unbias(d_1.table);
    return (_e30 * _e32);
}

FurRows fur_rows(FurDensity d_2, uint row_1, float w, float origin) {
    return FurRows(d_2, min(row_1, (d_2.rows - 1u)), min((row_1 + 1u), (d_2.rows - 1u)), w, origin, 0u);
}

FurRows fur_rows_weighted(uint weighting, uint row_2, float w_1) {
    FurDensity _e8 = fur_density(((weighting == 2u) ? 9u : 6u));
    return FurRows(_e8, min(row_2, (_e8.rows - 1u)), min((row_2 + 1u), (_e8.rows - 1u)), w_1, 0.0, weighting);
}

float fur_rows_value(FurRows r_1, uint j_1) {
    float _e4 = fur_node(r_1.d, r_1.r0_, j_1);
    if ((r_1.w == 0.0)) {
        return _e4;
    }
    float _e10 = fur_node(r_1.d, r_1.r1_, j_1);
    return (((1.0 - r_1.w) * _e4) + (r_1.w * _e10));
}

float fur_blended_prefix(FurRows r_2, FurDensity d_3, uint k_2) {
    float _e11 = fur_f32_at((d_3.prefix_at + (4u * ((r_2.r0_ * d_3.entries) + k_2))));
    if ((r_2.w == 0.0)) {
        return _e11;
    }
    float _e23 = fur_f32_at((d_3.prefix_at + (4u * ((r_2.r1_ * d_3.entries) + k_2))));
    return (((1.0 - r_2.w) * _e11) + (r_2.w * _e23));
}

float fur_rows_prefix(FurRows r_3, uint k_3) {
    float _e3 = fur_blended_prefix(r_3, r_3.d, k_3);
    if ((r_3.weighting == 1u)) {
        FurDensity _e8 = fur_density(9u);
        float _e9 = fur_blended_prefix(r_3, _e8, k_3);
        return (_e3 - _e9);
    }
    return _e3;
}

float fur_rows_total(FurRows r_4) {
    float _e5 = fur_rows_prefix(r_4, (r_4.d.entries - 1u));
    return _e5;
}

float fur_linear_mass(float v0_, float v1_, float len) {
    return ((0.5 * len) * (v0_ + v1_));
}

float fur_invert_linear(float v0_1, float v1_1, float len_1, float t_2) {
    float s = 0.0;
    bool local_12 = false;
    bool local_13 = false;
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

float fur_weighted_linear_mass(float v0_2, float v1_2, float a_1, float b, float len_2) {
    return ((len_2 * (((a_1 * v0_2) + (0.5 * ((a_1 * v1_2) + (b * v0_2)))) + (b * v1_2))) * 0.33333334);
}

float fur_invert_weighted_linear(float v0_3, float v1_3, float a_2, float b_1, float len_3, float t_3) {
    float x_7 = 0.5;
    bool local_14 = false;
    float lo = 0.0;
    float hi = 1.0;
    uint k_4 = 0u;
    float next = 0.0;
    bool local_15 = false;
    bool local_16 = false;
    bool local_17 = false;
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
        float _e43 = fur_invert_linear(q0_, q1_, 1.0, (goal * (lin / total_1)));
        x_7 = _e43;
    }
    bool loop_init_9 = true;
    while(true) {
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

vec2 fur_rows_weights(FurRows r_5, uint j_2) {
    float inv = (1.0 / float((r_5.d.nodes - 1u)));
    vec2 ab = vec2((float(j_2) * inv), (float((j_2 + 1u)) * inv));
    if ((r_5.weighting == 1u)) {
        return vec2((1.0 - ab.x), (1.0 - ab.y));
    }
    return ab;
}

float fur_rows_segment_mass(FurRows r_6, uint j_3, float v0_4, float v1_4) {
    if ((r_6.weighting == 0u)) {
        float _e9 = fur_linear_mass(v0_4, v1_4, r_6.d.step_);
        return _e9;
    }
    vec2 _e10 = fur_rows_weights(r_6, j_3);
    float _e15 = fur_weighted_linear_mass(v0_4, v1_4, _e10.x, _e10.y, r_6.d.step_);
    return _e15;
}

float fur_rows_invert_segment(FurRows r_7, uint j_4, float v0_5, float v1_5, float t_4) {
    if ((r_7.weighting == 0u)) {
        float _e10 = fur_invert_linear(v0_5, v1_5, r_7.d.step_, t_4);
        return _e10;
    }
    vec2 _e11 = fur_rows_weights(r_7, j_4);
    float _e16 = fur_invert_weighted_linear(v0_5, v1_5, _e11.x, _e11.y, r_7.d.step_, t_4);
    return _e16;
}

float fur_unit(float u_2) {
    if ((u_2 > 0.0)) {
        return min(u_2, 0.99999994);
    }
    return 0.0;
}

float fur_rows_invert(FurRows r_8, float t_5) {
    uint lo_1 = 0u;
    uint len_4 = 0u;
    float acc_2 = 0.0;
    float prev = 0.0;
    bool have_last = false;
    uint last_j = 0u;
    float last_v0_ = 0.0;
    float last_v1_ = 0.0;
    float last_m = 0.0;
    uint j_5 = 0u;
    len_4 = (r_8.d.entries - 1u);
    while(true) {
        uint _e9 = len_4;
        if ((_e9 <= 1u)) {
            break;
        }
        uint _e12 = len_4;
        uint half_1 = (_e12 / 2u);
        uint _e15 = lo_1;
        uint _e16 = lo_1;
        uint _e18 = lo_1;
        float _e20 = fur_rows_prefix(r_8, (_e18 + half_1));
        lo_1 = ((_e20 < t_5) ? (_e16 + half_1) : _e15);
        uint _e23 = len_4;
        len_4 = (_e23 - half_1);
    }
    uint _e25 = lo_1;
    uint first = (_e25 * r_8.d.block);
    uint end = min((first + r_8.d.block), (r_8.d.nodes - 1u));
    uint _e37 = lo_1;
    float _e38 = fur_rows_prefix(r_8, _e37);
    acc_2 = _e38;
    float _e40 = fur_rows_value(r_8, first);
    prev = _e40;
    j_5 = first;
    bool loop_init_10 = true;
    while(true) {
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
            float _e58 = fur_rows_value(r_8, (_e55 + 1u));
            uint _e59 = j_5;
            float _e60 = prev;
            float _e61 = fur_rows_segment_mass(r_8, _e59, _e60, _e58);
            if ((_e61 > 0.0)) {
                float _e64 = acc_2;
                if (((t_5 - _e64) <= _e61)) {
                    uint _e67 = j_5;
                    float _e68 = prev;
                    float _e69 = acc_2;
                    float _e71 = fur_rows_invert_segment(r_8, _e67, _e68, _e58, (t_5 - _e69));
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
        float _e103 = fur_rows_invert_segment(r_8, _e100, _e101, _e102, whole);
        uint _e105 = last_j;
        return ((r_8.origin + (float(_e105) * r_8.d.step_)) + _e103);
    }
    return (r_8.origin + (float(end) * r_8.d.step_));
}

float fur_rows_invert_between(FurRows r_9, float t0_, float t1_, float u_3) {
    float inset_2 = ((t1_ - t0_) * 9.536743e-7);
    float _e7 = fur_unit(u_3);
    float t_13 = clamp((t0_ + (_e7 * (t1_ - t0_))), (t0_ + inset_2), (t1_ - inset_2));
    float _e14 = fur_rows_invert(r_9, t_13);
    return _e14;
}

float fur_pole_keep(float cos_theta_i) {
    float c_3 = max(cos_theta_i, 1e-6);
    return min(((c_3 * c_3) * 10000.0), 1.0);
}

float fur_sliver_keep(float s_in) {
    float s_3 = abs(s_in);
    if (!((s_3 < FUR_POLE_SLIVER))) {
        return 1.0;
    }
    float s2_ = (s_3 * s_3);
    return min(((s2_ * (1.0 - (s2_ * 0.33333334))) * 10000.0), 1.0);
}

float fur_sliver_piece_mass(float v0_6, float v1_6, float len0_, float x0_, float pole, float len_5) {
    bool local_18 = false;
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
    float t_14[3] = float[3](0.11270166, 0.5, 0.8872983);
    float w_5[3] = float[3](0.2777778, 0.44444445, 0.2777778);
    bool loop_init_11 = true;
    while(true) {
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
            float d_8 = (t_14[_e33] * len_5);
            float _e36 = acc_3;
            uint _e37 = k_5;
            float _e44 = fur_sliver_keep(((x0_ - pole) + d_8));
            acc_3 = (_e36 + ((w_5[_e37] * (v0_6 + (slope * d_8))) * _e44));
        }
    }
    float _e50 = acc_3;
    return (_e50 * len_5);
}

float fur_invert_sliver_piece(float v0_7, float v1_7, float len_6, float x0_1, float pole_1, float t_6) {
    bool local_19 = false;
    float lo_2 = 0.0;
    float hi_1 = 0.0;
    float d_4 = 0.0;
    uint k_6 = 0u;
    float next_1 = 0.0;
    bool local_20 = false;
    float _e6 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, len_6);
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
    bool loop_init_12 = true;
    while(true) {
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
            float _e35 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, _e34);
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
            float _e47 = fur_sliver_keep(((x0_1 - pole_1) + _e45));
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

vec3 fur_rows_sliver(FurRows r_10, FurAxis ax, float a_3, float b_2, float pole_2, float t_7) {
    float off = 0.0;
    vec3 out_1 = vec3(0.0);
    uint j_6 = 0u;
    bool local_21 = false;
    bool local_22 = false;
    FurLoc _e6 = fur_locate(ax, a_3);
    FurLoc _e7 = fur_locate(ax, b_2);
    float at_2 = (a_3 - pole_2);
    out_1 = vec3(0.0, 0.0, b_2);
    j_6 = _e6.i;
    bool loop_init_13 = true;
    while(true) {
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
                float _e34 = fur_rows_value(r_10, _e33);
                uint _e35 = j_6;
                float _e38 = fur_rows_value(r_10, (_e35 + 1u));
                float len_7 = ((w1_2 - w0_2) * r_10.d.step_);
                float v0_9 = (_e34 + ((_e38 - _e34) * w0_2));
                float v1_9 = (_e34 + ((_e38 - _e34) * w1_2));
                float _e49 = off;
                float _e52 = fur_sliver_piece_mass(v0_9, v1_9, len_7, (at_2 + _e49), 0.0, len_7);
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
                    float _e77 = fur_invert_sliver_piece(v0_9, v1_9, len_7, (at_2 + _e71), 0.0, (t_7 - _e75));
                    out_1.z = (a_3 + (_e70 + _e77));
                    vec3 _e80 = out_1;
                    return _e80;
                }
                float _e83 = out_1.x;
                float _e84 = fur_linear_mass(v0_9, v1_9, len_7);
                out_1.x = (_e83 + _e84);
                float _e88 = out_1.y;
                out_1.y = (_e88 + _e52);
                float _e90 = off;
                off = (_e90 + len_7);
            }
        }
    }
    vec3 _e95 = out_1;
    return _e95;
}

FurRange fur_rows_range(FurRows r_11, FurAxis ax_1, float lo_3, float hi_2, float start, float raw) {
    vec3 _e9 = fur_rows_sliver(r_11, ax_1, lo_3, (lo_3 + FUR_POLE_SLIVER), lo_3, -1.0);
    vec3 _e13 = fur_rows_sliver(r_11, ax_1, (hi_2 - FUR_POLE_SLIVER), hi_2, hi_2, -1.0);
    return FurRange(lo_3, hi_2, start, raw, vec4(_e9.x, _e9.y, _e13.x, _e13.y));
}

float fur_range_kept(FurRange g_1) {
    return ((max(((g_1.raw - g_1.s.x) - g_1.s.z), 0.0) + g_1.s.y) + g_1.s.w);
}

float fur_rows_invert_kept(FurRows r_12, FurAxis ax_2, FurRange g_2, float u_4) {
    bool local_23 = false;
    float _e4 = fur_range_kept(g_2);
    float inset_3 = (_e4 * 9.536743e-7);
    float _e7 = fur_unit(u_4);
    float t0_1 = clamp((_e7 * _e4), inset_3, (_e4 - inset_3));
    if ((t0_1 < g_2.s.y)) {
        vec3 _e19 = fur_rows_sliver(r_12, ax_2, g_2.lo, (g_2.lo + FUR_POLE_SLIVER), g_2.lo, t0_1);
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
        float _e50 = fur_rows_invert(r_12, ((g_2.start + g_2.s.x) + min(t_15, mid)));
        return _e50;
    }
    vec3 _e57 = fur_rows_sliver(r_12, ax_2, (g_2.hi - FUR_POLE_SLIVER), g_2.hi, g_2.hi, (t_15 - mid));
    return _e57.z;
}

FurAxis fur_sum_axis() {
    uint _e3 = fur_word(4u);
    FurAxis _e4 = fur_axis(true, 0.15915494, _e3);
    return _e4;
}

FurMAt fur_m_at(FurLoc l_1) {
    FurMAt out_2 = FurMAt(vec3(0.0), vec3(0.0));
    uint g_3 = 0u;
    FurDensity _e2 = fur_density(0u);
    float off_1 = (l_1.w * _e2.step_);
    bool loop_init_14 = true;
    while(true) {
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
            FurDensity _e18 = fur_density(_e17);
            float _e21 = fur_node(_e18, 0u, l_1.i);
            float _e26 = fur_node(_e18, 0u, (l_1.i + 1u));
            float at_3 = (_e21 + ((_e26 - _e21) * l_1.w));
            uint _e32 = g_3;
            float _e39 = fur_f32_at((_e18.prefix_at + (4u * l_1.i)));
            float _e40 = fur_linear_mass(_e21, at_3, off_1);
            out_2.cdf[_e32] = (_e39 + _e40);
            uint _e43 = g_3;
            out_2.value[_e43] = at_3;
        }
    }
    FurMAt _e48 = out_2;
    return _e48;
}

vec3 fur_m_cdf(float x_8) {
    FurAxis _e1 = fur_sum_axis();
    FurLoc _e2 = fur_locate(_e1, x_8);
    FurMAt _e3 = fur_m_at(_e2);
    return _e3.cdf;
}

float fur_row_total(FurDensity d_5, FurLoc l_2) {
    float _e17 = fur_f32_at((d_5.prefix_at + (4u * (((min(l_2.i, (d_5.rows - 1u)) * d_5.entries) + d_5.entries) - 1u))));
    float _e35 = fur_f32_at((d_5.prefix_at + (4u * (((min((l_2.i + 1u), (d_5.rows - 1u)) * d_5.entries) + d_5.entries) - 1u))));
    return (_e17 + ((_e35 - _e17) * l_2.w));
}

float fur_positive(float v) {
    bool local_24 = false;
    bool _e1 = fur_finite(v);
    if (_e1) {
        local_24 = (v > 0.0);
    } else {
        local_24 = false;
    }
    bool _e7 = local_24;
    return (_e7 ? v : 0.0);
}

FurAxis fur_ms_i_axis() {
    uint _e3 = fur_word(7u);
    FurAxis _e4 = fur_axis(true, 0.31830987, _e3);
    return _e4;
}

FurRows fur_ms_rows(uint half_, float theta_r_4) {
    uint _e5 = fur_word(8u);
    FurAxis _e6 = fur_axis(true, 0.31830987, _e5);
    FurLoc _e7 = fur_locate(_e6, theta_r_4);
    FurDensity _e10 = fur_density((7u + half_));
    FurRows _e14 = fur_rows(_e10, _e7.i, _e7.w, -1.5707964);
    return _e14;
}

FurParts fur_parts(float theta_r_5) {
    FurRange ranges[5] = FurRange[5](FurRange(0.0, 0.0, 0.0, 0.0, vec4(0.0)), FurRange(0.0, 0.0, 0.0, 0.0, vec4(0.0)), FurRange(0.0, 0.0, 0.0, 0.0, vec4(0.0)), FurRange(0.0, 0.0, 0.0, 0.0, vec4(0.0)), FurRange(0.0, 0.0, 0.0, 0.0, vec4(0.0)));
    uint g_4 = 0u;
    uint x_9 = 0u;
    float lo_x = (theta_r_5 - FUR_HALF_PI);
    float hi_x = (theta_r_5 + FUR_HALF_PI);
    vec3 _e5 = fur_m_cdf(lo_x);
    vec3 _e6 = fur_m_cdf(hi_x);
    vec3 mass = max((_e6 - _e5), vec3(0.0));
    uint _e14 = fur_word(5u);
    FurAxis _e15 = fur_axis(false, 0.63661975, _e14);
    FurLoc _e17 = fur_locate(_e15, abs(theta_r_5));
    FurDensity _e19 = fur_density(6u);
    float _e20 = fur_row_total(_e19, _e17);
    FurDensity _e22 = fur_density(9u);
    float _e23 = fur_row_total(_e22, _e17);
    bool loop_init_15 = true;
    while(true) {
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
            FurDensity _e31 = fur_density(_e30);
            FurRows _e35 = fur_rows(_e31, 0u, 0.0, -3.1415927);
            uint _e36 = g_4;
            FurAxis _e38 = fur_sum_axis();
            uint _e39 = g_4;
            uint _e41 = g_4;
            FurRange _e43 = fur_rows_range(_e35, _e38, lo_x, hi_x, _e5[_e39], mass[_e41]);
            ranges[_e36] = _e43;
        }
    }
    bool loop_init_16 = true;
    while(true) {
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
            FurRows _e53 = fur_ms_rows(_e52, theta_r_5);
            uint _e55 = x_9;
            FurAxis _e58 = fur_ms_i_axis();
            float _e62 = fur_rows_total(_e53);
            FurRange _e63 = fur_rows_range(_e53, _e58, -1.5707964, FUR_HALF_PI, 0.0, _e62);
            ranges[(3u + _e55)] = _e63;
        }
    }
    FurRange _e68 = ranges[0];
    float _e69 = fur_range_kept(_e68);
    FurRange _e71 = ranges[1];
    float _e72 = fur_range_kept(_e71);
    FurRange _e74 = ranges[2];
    float _e75 = fur_range_kept(_e74);
    vec3 _e77 = fur_sphere_norms(theta_r_5);
    vec3 kept = (vec3(_e69, _e72, _e75) * _e77);
    FurDensity _e83 = fur_density(3u);
    float _e84 = fur_row_total(_e83, _e17);
    float _e86 = fur_positive(((2.0 * kept.x) * _e84));
    FurDensity _e91 = fur_density(4u);
    float _e92 = fur_row_total(_e91, _e17);
    float _e94 = fur_positive(((2.0 * kept.y) * _e92));
    FurDensity _e99 = fur_density(5u);
    float _e100 = fur_row_total(_e99, _e17);
    float _e102 = fur_positive(((2.0 * kept.z) * _e100));
    FurRange _e104 = ranges[3];
    float _e105 = fur_range_kept(_e104);
    float _e110 = fur_positive(((2.0 * _e105) * (_e20 - _e23)));
    FurRange _e112 = ranges[4];
    float _e113 = fur_range_kept(_e112);
    float _e117 = fur_positive(((2.0 * _e113) * _e23));
    float a_10[5] = float[5](_e86, _e94, _e102, _e110, _e117);
    FurRange _e119[5] = ranges;
    return FurParts(a_10, _e119);
}

float fur_density_of(FurLookups l_3, float w_2, float cos_theta_i_1) {
    if (!((w_2 > 0.0))) {
        return 0.0;
    }
    float ms_1 = (l_3.ms[0] + (l_3.front * (l_3.ms[1] - l_3.ms[0])));
    float p_5 = ((((l_3.m[0] * l_3.n0_[0]) + (l_3.m[1] * l_3.n0_[1])) + (l_3.m[2] * l_3.n0_[2])) + (ms_1 * l_3.n0_[3]));
    float _e38 = fur_pole_keep(cos_theta_i_1);
    float pg = (p_5 * _e38);
    float _e44 = fur_positive(((pg / w_2) / max(cos_theta_i_1, 1e-6)));
    return _e44;
}

float fur_pdf_far(float theta_i_3, float theta_r_6, float phi_2, vec3 sigma_ca_4) {
    bool _e4 = fur_valid(theta_i_3, theta_r_6, phi_2);
    if (!(_e4)) {
        return 0.0;
    }
    FurParts _e7 = fur_parts(theta_r_6);
    float w_6 = ((((_e7.a[0] + _e7.a[1]) + _e7.a[2]) + _e7.a[3]) + _e7.a[4]);
    FurLookups _e22 = fur_lookups(theta_i_3, theta_r_6, phi_2, sigma_ca_4);
    float _e23 = fur_cos_within_half_pi(theta_i_3);
    float _e24 = fur_density_of(_e22, w_6, _e23);
    return _e24;
}

FurSample fur_sample_far(float theta_r_7, vec3 u_5, vec3 sigma_ca_5) {
    FurSample out_3 = FurSample(0.0, 0.0, 0.0, vec3(0.0), 0u, false);
    bool local_25 = false;
    float total = 0.0;
    uint k_7 = 0u;
    float acc_4 = 0.0;
    uint c_1 = 5u;
    float u0_ = 0.0;
    uint last = 5u;
    uint k_8 = 0u;
    float theta_i_4 = 0.0;
    FurRows nrows = FurRows(FurDensity(0u, 0u, 0u, 0u, 0.0, 0u, 0u, 0u), 0u, 0u, 0.0, 0.0, 0u);
    bool local_26 = false;
    bool _e12 = fur_finite(theta_r_7);
    if (_e12) {
        local_25 = (abs(theta_r_7) <= FUR_HALF_PI);
    } else {
        local_25 = false;
    }
    bool _e19 = local_25;
    if (!(_e19)) {
        FurSample _e21 = out_3;
        return _e21;
    }
    FurParts _e22 = fur_parts(theta_r_7);
    bool loop_init_17 = true;
    while(true) {
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
            total = (_e30 + _e22.a[_e32]);
        }
    }
    float _e38 = total;
    if (!((_e38 > 0.0))) {
        FurSample _e42 = out_3;
        return _e42;
    }
    float _e44 = fur_unit(u_5.x);
    float _e45 = total;
    float target_mass = (_e44 * _e45);
    bool loop_init_18 = true;
    while(true) {
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
            float wk = _e22.a[_e61];
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
                float _e74 = fur_unit(((target_mass - _e71) / wk));
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
        FurDensity _e108 = fur_density(_e107);
        FurRows _e112 = fur_rows(_e108, 0u, 0.0, -3.1415927);
        FurAxis _e113 = fur_sum_axis();
        uint _e115 = c_1;
        float _e118 = fur_rows_invert_kept(_e112, _e113, _e22.ranges[_e115], u_5.y);
        theta_i_4 = clamp((_e118 - theta_r_7), -1.5707964, FUR_HALF_PI);
    } else {
        uint _e123 = c_1;
        FurRows _e126 = fur_ms_rows((_e123 - 3u), theta_r_7);
        FurAxis _e127 = fur_ms_i_axis();
        uint _e129 = c_1;
        float _e132 = fur_rows_invert_kept(_e126, _e127, _e22.ranges[_e129], u_5.y);
        theta_i_4 = clamp(_e132, -1.5707964, FUR_HALF_PI);
    }
    uint _e136 = c_1;
    uint family = min(_e136, 3u);
    uint _e142 = fur_word(5u);
    FurAxis _e143 = fur_axis(false, 0.63661975, _e142);
    FurLoc _e145 = fur_locate(_e143, abs(theta_r_7));
    FurDensity _e148 = fur_density((3u + family));
    FurRows _e152 = fur_rows(_e148, _e145.i, _e145.w, 0.0);
    nrows = _e152;
    uint _e154 = c_1;
    if ((_e154 >= 3u)) {
        uint _e157 = c_1;
        FurRows _e162 = fur_rows_weighted((_e157 - 2u), _e145.i, _e145.w);
        nrows = _e162;
    }
    FurRows _e163 = nrows;
    FurRows _e165 = nrows;
    float _e166 = fur_rows_total(_e165);
    float _e168 = fur_rows_invert_between(_e163, 0.0, _e166, u_5.z);
    float abs_phi_1 = clamp(_e168, 0.0, FUR_PI);
    float _e174 = fur_wrap_angle((negative ? -(abs_phi_1) : abs_phi_1));
    float _e175 = theta_i_4;
    FurLookups _e176 = fur_lookups(_e175, theta_r_7, _e174, sigma_ca_5);
    float _e177 = theta_i_4;
    float _e178 = fur_cos_within_half_pi(_e177);
    float _e179 = fur_density_of(_e176, total_weight, _e178);
    if ((_e179 > 0.0)) {
        bool _e184 = fur_finite(_e179);
        local_26 = _e184;
    } else {
        local_26 = false;
    }
    bool _e186 = local_26;
    if (!(_e186)) {
        FurSample _e188 = out_3;
        return _e188;
    }
    FurFamilies _e189 = fur_assemble(_e176);
    float _e190 = theta_i_4;
    float k_19 = (max(cos(_e190), 0.0) / _e179);
    float _e195 = theta_i_4;
    out_3 = FurSample(_e195, _e174, _e179, max((_e189.total * k_19), vec3(0.0)), family, true);
    FurSample _e203 = out_3;
    return _e203;
}

vec3 fur_dual_sigma_node(uvec3 k_9) {
    vec3 v_3 = ((vec3(k_9) / vec3(15.0)) * 0.997009);
    return mix(((FUR_DUAL_KNEE * v_3) / (vec3(1.0) - v_3)), vec3(1000.0), greaterThanEqual(k_9, uvec3(15u)));
}

FurDualColour fur_dual_locate(vec3 sigma_in) {
    uvec3 k_10 = uvec3(0u);
    vec3 w_3 = vec3(0.0);
    bvec3 _e9 = fur_is_nan3_(sigma_in);
    vec3 s_4 = mix(min(max(sigma_in, vec3(0.0)), vec3(1000.0)), vec3(0.0), _e9);
    vec3 coord = min(((s_4 / (s_4 + vec3(3.0))) / vec3(0.997009)), vec3(1.0));
    vec3 u_9 = clamp((coord * 15.0), vec3(0.0), vec3(15.0));
    k_10 = min(uvec3(u_9), uvec3(14u));
    uvec3 _e32 = k_10;
    vec3 _e33 = fur_dual_sigma_node(_e32);
    vec3 lo_4 = sqrt(_e33);
    uvec3 _e35 = k_10;
    vec3 _e39 = fur_dual_sigma_node((_e35 + uvec3(1u)));
    vec3 hi_3 = sqrt(_e39);
    w_3 = clamp(((sqrt(s_4) - lo_4) / (hi_3 - lo_4)), vec3(0.0), vec3(1.0));
    vec3 _e51 = w_3;
    vec3 _e54 = w_3;
    bvec3 _e55 = fur_is_nan3_(_e54);
    vec3 _e56 = w_3;
    w_3 = mix(_e51, vec3(0.0), bvec3(_e55.x || lessThan(_e56, vec3(0.0001)).x, _e55.y || lessThan(_e56, vec3(0.0001)).y, _e55.z || lessThan(_e56, vec3(0.0001)).z));
    vec3 _e62 = w_3;
    uvec3 _e66 = k_10;
    bvec3 up = bvec3(greaterThan(_e62, vec3(0.9999)).x && lessThan((_e66 + uvec3(2u)), uvec3(16u)).x, greaterThan(_e62, vec3(0.9999)).y && lessThan((_e66 + uvec3(2u)), uvec3(16u)).y, greaterThan(_e62, vec3(0.9999)).z && lessThan((_e66 + uvec3(2u)), uvec3(16u)).z);
    uvec3 _e74 = k_10;
    uvec3 _e75 = k_10;
    k_10 = mix(_e74, (_e75 + uvec3(1u)), up);
    vec3 _e80 = w_3;
    w_3 = mix(_e80, vec3(0.0), up);
    vec3 _e84 = w_3;
    vec3 _e87 = w_3;
    w_3 = mix(_e84, vec3(1.0), greaterThan(_e87, vec3(0.9999)));
    uvec3 _e92 = k_10;
    vec3 _e93 = w_3;
    return FurDualColour(_e92, _e93);
}

bool fur_is_nan(float x_10) {
    return ((floatBitsToUint(x_10) & 2147483647u) > 2139095040u);
}

FurLoc fur_dual_theta(float theta) {
    float t_8 = 0.0;
    t_8 = (((theta + FUR_HALF_PI) * FUR_DUAL_THETA_SCALE) - 0.5);
    float _e8 = t_8;
    float _e9 = t_8;
    t_8 = ((_e9 > 0.0) ? _e8 : 0.0);
    float _e14 = t_8;
    t_8 = min(_e14, 63.0);
    float _e17 = t_8;
    uint k_20 = min(uint(_e17), 62u);
    float _e21 = t_8;
    return FurLoc(k_20, (_e21 - float(k_20)));
}

vec3 fur_rsqrt_newton(vec3 v_1) {
    vec3 y_2 = vec3(0.0);
    y_2 = uintBitsToFloat((uvec3(1597463174u) - (floatBitsToUint(v_1) >> uvec3(1u))));
    vec3 h_4 = (0.5 * v_1);
    vec3 _e12 = y_2;
    vec3 _e13 = y_2;
    vec3 _e15 = y_2;
    y_2 = (_e12 * (vec3(1.5) - ((h_4 * _e13) * _e15)));
    vec3 _e21 = y_2;
    vec3 _e22 = y_2;
    vec3 _e24 = y_2;
    y_2 = (_e21 * (vec3(1.5) - ((h_4 * _e22) * _e24)));
    vec3 _e30 = y_2;
    vec3 _e31 = y_2;
    vec3 _e33 = y_2;
    return (_e30 * (vec3(1.5) - ((h_4 * _e31) * _e33)));
}

vec3 fur_exp_neg(vec3 x_in) {
    vec3 p_2 = vec3(0.00019875693);
    vec3 x_19 = min(max(x_in, vec3(0.0)), vec3(87.0));
    vec3 k_21 = roundEven((x_19 * FUR_LOG2_E));
    vec3 r_16 = (((k_21 * FUR_LN2_HI) - x_19) + (k_21 * FUR_LN2_LO));
    vec3 z_1 = (r_16 * r_16);
    vec3 _e20 = p_2;
    p_2 = ((_e20 * r_16) + vec3(0.0013981999));
    vec3 _e25 = p_2;
    p_2 = ((_e25 * r_16) + vec3(0.008333452));
    vec3 _e30 = p_2;
    p_2 = ((_e30 * r_16) + vec3(0.041665796));
    vec3 _e35 = p_2;
    p_2 = ((_e35 * r_16) + vec3(0.16666666));
    vec3 _e40 = p_2;
    p_2 = ((_e40 * r_16) + vec3(0.5));
    vec3 _e45 = p_2;
    vec3 e_1 = (((_e45 * z_1) + r_16) + vec3(1.0));
    return mix(ldexp(e_1, -(ivec3(k_21))), vec3(0.0), greaterThan(x_in, vec3(87.0)));
}

vec3 fur_erf(vec3 x_11) {
    bvec3 _e7 = fur_is_nan3_(x_11);
    vec3 a_11 = mix(min(abs(x_11), vec3(10.0)), vec3(0.0), _e7);
    vec3 p_6 = ((((((((((((FUR_ERF_A6_ * a_11) + vec3(0.0002765672)) * a_11) + vec3(0.0001520143)) * a_11) + vec3(0.009270527)) * a_11) + vec3(0.04228201)) * a_11) + vec3(0.07052308)) * a_11) + vec3(1.0));
    vec3 p2_ = (p_6 * p_6);
    vec3 p4_ = (p2_ * p2_);
    vec3 p8_ = (p4_ * p4_);
    vec3 e_2 = (vec3(1.0) - (vec3(1.0) / (p8_ * p8_)));
    uvec3 sign_ = (floatBitsToUint(x_11) & uvec3(2147483648u));
    return uintBitsToFloat((floatBitsToUint(e_2) | sign_));
}

vec3 fur_dual_between(vec3 x_12, vec3 top) {
    bvec3 _e8 = fur_is_nan3_(x_12);
    return mix(min(max(x_12, vec3(0.0)), top), vec3(0.0), _e8);
}

vec3 fur_dual_gauss(vec3 d_6, vec3 v_in, float theta_i_5) {
    vec3 v_4 = clamp(v_in, vec3(3e-6), vec3(1e30));
    vec3 _e8 = fur_rsqrt_newton(v_4);
    vec3 z_2 = (d_6 * _e8);
    vec3 _e13 = fur_exp_neg(((0.5 * z_2) * z_2));
    vec3 g_8 = ((_e13 * _e8) * FUR_INV_SQRT_TAU);
    vec3 centre = (((d_6 - vec3(theta_i_5)) * _e8) * FUR_FRAC_1_SQRT_2_);
    vec3 half_range = ((FUR_HALF_PI * _e8) * FUR_FRAC_1_SQRT_2_);
    vec3 _e27 = fur_erf((centre + half_range));
    vec3 _e29 = fur_erf((centre - half_range));
    vec3 mass_1 = (0.5 * (_e27 - _e29));
    return (g_8 / max(mass_1, vec3(0.05)));
}

vec3 fur_dual_power(vec3 log2_mu, float k_12) {
    vec3 _e6 = fur_exp_neg(((-(k_12) * FUR_LN2_) * log2_mu));
    return _e6;
}

vec3 fur_reflectance_squared(vec3 mu, vec3 t_9) {
    vec3 den_1 = (mu * (vec3(1.0) - (t_9 * mu)));
    vec3 _e14 = fur_dual_between(((mu - t_9) / max(den_1, vec3(1e-6))), vec3(1.0));
    return mix(vec3(0.0), _e14, greaterThan(den_1, vec3(1e-6)));
}

vec3 fur_downward_flux(vec3 mu_n, vec3 mu_2m, vec3 rho2_) {
    vec3 num = (vec3(1.0) - (rho2_ * mu_2m));
    vec3 den_2 = (vec3(1.0) - (((rho2_ * mu_n) * mu_n) * mu_2m));
    vec3 d_9 = (mu_n * (num / max(den_2, vec3(1e-6))));
    vec3 _e18 = fur_dual_between(d_9, mu_n);
    return mix(mu_n, _e18, greaterThan(den_2, vec3(1e-6)));
}

vec3 fur_backscatter_factor(vec3 rho2_1, vec3 mu_1, vec3 mu_2m_1) {
    vec3 tiny = vec3(1e-6);
    vec3 g_den = (vec3(1.0) - (rho2_1 * mu_2m_1));
    vec3 _e16 = fur_dual_between(((vec3(1.0) - mu_2m_1) / max(g_den, tiny)), vec3(1.0));
    return (mix(vec3(1.0), _e16, greaterThan(g_den, tiny)) / max(mu_1, tiny));
}

float fur_dual_clean(float x_13, float top_1) {
    bool local_27 = false;
    bool _e3 = fur_is_nan(x_13);
    if (!(_e3)) {
        local_27 = (x_13 > 0.0);
    } else {
        local_27 = false;
    }
    bool _e10 = local_27;
    return (_e10 ? min(x_13, top_1) : 0.0);
}

float fur_dual_below(float x_14) {
    bool local_28 = false;
    bool _e2 = fur_is_nan(x_14);
    float deep = (_e2 ? FUR_DUAL_MAX_FIBERS : 0.0);
    bool _e9 = fur_is_nan(x_14);
    if (!(_e9)) {
        local_28 = (x_14 >= 0.0);
    } else {
        local_28 = false;
    }
    bool _e16 = local_28;
    return (_e16 ? min((x_14 + FUR_DUAL_LINE_SAMPLE_OFFSET), FUR_DUAL_MAX_FIBERS) : deep);
}

float fur_dual_below_at_incidence(float count_on_line, float cos_to_skin) {
    bool local_29 = false;
    bool local_30 = false;
    bool local_31 = false;
    float skin_layers = ((FUR_DUAL_DIFFUSIVITY * min(abs(cos_to_skin), 1.0)) * (count_on_line + FUR_DUAL_LINE_SAMPLE_OFFSET));
    float as_count = max((skin_layers - FUR_DUAL_LINE_SAMPLE_OFFSET), 0.0);
    bool _e14 = fur_is_nan(count_on_line);
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
        bool _e30 = fur_is_nan(cos_to_skin);
        local_31 = !(_e30);
    } else {
        local_31 = false;
    }
    bool known = local_31;
    return (known ? as_count : count_on_line);
}

float fur_dual_forward_density_at_incidence(float d_f, float cos_to_skin_1) {
    float scaled = ((d_f * FUR_DUAL_DIFFUSIVITY) * min(abs(cos_to_skin_1), 1.0));
    bool _e8 = fur_is_nan(cos_to_skin_1);
    return (_e8 ? d_f : scaled);
}

float fur_coat_sigma_at(float x_15) {
    float x2_1 = (x_15 * x_15);
    return clamp((x2_1 / max((1.0 - x2_1), 1e-12)), 0.0, FUR_SIGMA_CA_MAX);
}

float fur_coat_sigma_for(vec4 table[6], float c_2) {
    vec4 nodes_2[6] = vec4[6](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    uint k_14 = 0u;
    float t_10 = 0.0;
    nodes_2 = table;
    float _e5 = nodes_2[0].x;
    if ((c_2 >= _e5)) {
        return 0.0;
    }
    bool loop_init_19 = true;
    while(true) {
        if (!loop_init_19) {
            uint _e51 = k_14;
            k_14 = (_e51 + 1u);
        }
        loop_init_19 = false;
        uint _e10 = k_14;
        if ((_e10 < 23u)) {
        } else {
            break;
        }
        {
            uint _e13 = k_14;
            uint _e17 = k_14;
            float hi_4 = nodes_2[(_e13 / 4u)][(_e17 % 4u)];
            uint _e22 = k_14;
            uint _e28 = k_14;
            float lo_5 = nodes_2[((_e22 + 1u) / 4u)][((_e28 + 1u) % 4u)];
            if ((c_2 >= lo_5)) {
                t_10 = 0.0;
                if ((hi_4 > lo_5)) {
                    t_10 = ((hi_4 - c_2) / (hi_4 - lo_5));
                }
                uint _e42 = k_14;
                float _e44 = t_10;
                float x_20 = (((float(_e42) + _e44) / 23.0) * FUR_COAT_AXIS_END);
                float _e50 = fur_coat_sigma_at(x_20);
                return _e50;
            }
        }
    }
    return FUR_SIGMA_CA_MAX;
}

vec3 fur_absorption_from_colour(vec4 table_1[6], vec3 colour) {
    float _e3 = fur_coat_sigma_for(table_1, colour.x);
    float _e5 = fur_coat_sigma_for(table_1, colour.y);
    float _e7 = fur_coat_sigma_for(table_1, colour.z);
    return vec3(_e3, _e5, _e7);
}

void fur_store(uint q, FurFamilies f_5) {
    uint k_15 = 0u;
    uint base_1 = (16u * q);
    vec3 parts[5] = vec3[5](f_5.r, f_5.tt, f_5.trt, f_5.scattered, f_5.total);
    bool loop_init_20 = true;
    while(true) {
        if (!loop_init_20) {
            uint _e46 = k_15;
            k_15 = (_e46 + 1u);
        }
        loop_init_20 = false;
        uint _e12 = k_15;
        if ((_e12 < 5u)) {
        } else {
            break;
        }
        {
            uint _e17 = k_15;
            uint _e21 = k_15;
            _group_0_binding_2_cs[(base_1 + (3u * _e17))] = parts[_e21].x;
            uint _e26 = k_15;
            uint _e32 = k_15;
            _group_0_binding_2_cs[((base_1 + (3u * _e26)) + 1u)] = parts[_e32].y;
            uint _e37 = k_15;
            uint _e43 = k_15;
            _group_0_binding_2_cs[((base_1 + (3u * _e37)) + 2u)] = parts[_e43].z;
        }
    }
    _group_0_binding_2_cs[(base_1 + 15u)] = 0.0;
    return;
}

void fur_store_rgb(uint q_1, vec3 v_2) {
    uint k_16 = 3u;
    uint base_2 = (16u * q_1);
    _group_0_binding_2_cs[base_2] = v_2.x;
    _group_0_binding_2_cs[(base_2 + 1u)] = v_2.y;
    _group_0_binding_2_cs[(base_2 + 2u)] = v_2.z;
    bool loop_init_21 = true;
    while(true) {
        if (!loop_init_21) {
            uint _e27 = k_16;
            k_16 = (_e27 + 1u);
        }
        loop_init_21 = false;
        uint _e19 = k_16;
        if ((_e19 < 16u)) {
        } else {
            break;
        }
        {
            uint _e23 = k_16;
            _group_0_binding_2_cs[(base_2 + _e23)] = 0.0;
        }
    }
    return;
}

void main() {
    uvec3 id_2 = gl_GlobalInvocationID;
    uint q_2 = id_2.x;
    if ((((2u * q_2) + 1u) >= uint(_group_0_binding_1_cs.length()))) {
        return;
    }
    vec4 a_12 = _group_0_binding_1_cs[(2u * q_2)];
    vec4 _e22 = _group_0_binding_1_cs[((2u * q_2) + 1u)];
    FurSample _e24 = fur_sample_far(a_12.x, a_12.yzw, _e22.xyz);
    uint base_3 = (16u * q_2);
    _group_0_binding_2_cs[base_3] = _e24.theta_i;
    _group_0_binding_2_cs[(base_3 + 1u)] = _e24.phi;
    _group_0_binding_2_cs[(base_3 + 2u)] = _e24.pdf;
    _group_0_binding_2_cs[(base_3 + 3u)] = _e24.weight.x;
    _group_0_binding_2_cs[(base_3 + 4u)] = _e24.weight.y;
    _group_0_binding_2_cs[(base_3 + 5u)] = _e24.weight.z;
    _group_0_binding_2_cs[(base_3 + 6u)] = float(_e24.family);
    _group_0_binding_2_cs[(base_3 + 7u)] = (_e24.ok ? 1.0 : 0.0);
    return;
}

