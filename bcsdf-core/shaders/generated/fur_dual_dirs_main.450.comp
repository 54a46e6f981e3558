#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
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

layout(std430) readonly buffer type_1_block_0Compute { uint _group_0_binding_3_cs[]; };

FurDualColour fur_dual_at = FurDualColour(uvec3(0u), vec3(0.0));

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

FurFamilies fur_assemble(FurLookups l) {
    vec3 f_2[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint k_1 = 0u;
    float mss = (l.ms[0] + (l.front * (l.ms[1] - l.ms[0])));
    float lon[4] = float[4](l.m[0], l.m[1], l.m[2], mss);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e51 = k_1;
            k_1 = (_e51 + 1u);
        }
        loop_init = false;
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

float fur_asin(float x_5) {
    float ax_3 = min(abs(x_5), 1.0);
    float x2_ = (ax_3 * ax_3);
    float x4_ = (x2_ * x2_);
    float p01_1 = ((-0.001262491 * ax_3) + 0.00667009);
    float p23_1 = ((-0.017088126 * ax_3) + 0.03089188);
    float p45_1 = ((-0.050174303 * ax_3) + 0.08897899);
    float p67_1 = ((-0.2145988 * ax_3) + FUR_HALF_PI);
    float poly = ((((p01_1 * x2_) + p23_1) * x4_) + ((p45_1 * x2_) + p67_1));
    float r_14 = (FUR_HALF_PI - (sqrt((1.0 - ax_3)) * poly));
    return (((floatBitsToUint(x_5) & 2147483648u) != 0u) ? -(abs(r_14)) : abs(r_14));
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
    float t_11 = (a_8 * a_8);
    float _e10 = fur_atan_poly(t_11);
    r = (a_8 + (a_8 * (t_11 * _e10)));
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
    float x_16 = (dot(wi, wr) - (a_9 * b_3));
    float _e64 = fur_atan2_(y_6, x_16);
    return FurDirAngles(_e51, _e58, abs(_e64), true);
}

FurRows fur_rows(FurDensity d_2, uint row_1, float w, float origin) {
    return FurRows(d_2, min(row_1, (d_2.rows - 1u)), min((row_1 + 1u), (d_2.rows - 1u)), w, origin, 0u);
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
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e102 = k_4;
            k_4 = (_e102 + 1u);
        }
        loop_init_1 = false;
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

float fur_pole_keep(float cos_theta_i) {
    float c_3 = max(cos_theta_i, 1e-6);
    return min(((c_3 * c_3) * 10000.0), 1.0);
}

float fur_sliver_keep(float s_in) {
    float s_2 = abs(s_in);
    if (!((s_2 < FUR_POLE_SLIVER))) {
        return 1.0;
    }
    float s2_ = (s_2 * s_2);
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
    float t_12[3] = float[3](0.11270166, 0.5, 0.8872983);
    float w_4[3] = float[3](0.2777778, 0.44444445, 0.2777778);
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e47 = k_5;
            k_5 = (_e47 + 1u);
        }
        loop_init_2 = false;
        uint _e30 = k_5;
        if ((_e30 < 3u)) {
        } else {
            break;
        }
        {
            uint _e33 = k_5;
            float d_8 = (t_12[_e33] * len_5);
            float _e36 = acc_3;
            uint _e37 = k_5;
            float _e44 = fur_sliver_keep(((x0_ - pole) + d_8));
            acc_3 = (_e36 + ((w_4[_e37] * (v0_6 + (slope * d_8))) * _e44));
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
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e76 = k_6;
            k_6 = (_e76 + 1u);
        }
        loop_init_3 = false;
        uint _e31 = k_6;
        if ((_e31 < 16u)) {
        } else {
            break;
        }
        {
            float _e34 = d_4;
            float _e35 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, _e34);
            float f_7 = (_e35 - t_6);
            if ((f_7 > 0.0)) {
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
                float n_3 = (_e57 - (f_7 / dens));
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

float fur_range_kept(FurRange g_1) {
    return ((max(((g_1.raw - g_1.s.x) - g_1.s.z), 0.0) + g_1.s.y) + g_1.s.w);
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

float fur_dual_half(uint h_1) {
    uint _e7 = _group_0_binding_3_cs[(FUR_DUAL_HEADER_WORDS + (h_1 >> 1u))];
    vec2 pair = unpackHalf2x16(_e7);
    return (((h_1 & 1u) == 1u) ? pair.y : pair.x);
}

vec3 fur_dual_rgb(uvec3 a_4, uint h_2) {
    uvec3 n_4 = ((a_4 * FUR_DUAL_NODE_HALVES) + uvec3(h_2));
    float _e7 = fur_dual_half(n_4.x);
    float _e9 = fur_dual_half(n_4.y);
    float _e11 = fur_dual_half(n_4.z);
    return vec3(_e7, _e9, _e11);
}

vec3 fur_dual_sigma_node(uvec3 k_9) {
    vec3 v_3 = ((vec3(k_9) / vec3(15.0)) * 0.997009);
    return mix(((FUR_DUAL_KNEE * v_3) / (vec3(1.0) - v_3)), vec3(1000.0), greaterThanEqual(k_9, uvec3(15u)));
}

FurDualColour fur_dual_locate(vec3 sigma_in) {
    uvec3 k_10 = uvec3(0u);
    vec3 w_3 = vec3(0.0);
    bvec3 _e9 = fur_is_nan3_(sigma_in);
    vec3 s_3 = mix(min(max(sigma_in, vec3(0.0)), vec3(1000.0)), vec3(0.0), _e9);
    vec3 coord = min(((s_3 / (s_3 + vec3(3.0))) / vec3(0.997009)), vec3(1.0));
    vec3 u_8 = clamp((coord * 15.0), vec3(0.0), vec3(15.0));
    k_10 = min(uvec3(u_8), uvec3(14u));
    uvec3 _e32 = k_10;
    vec3 _e33 = fur_dual_sigma_node(_e32);
    vec3 lo_4 = sqrt(_e33);
    uvec3 _e35 = k_10;
    vec3 _e39 = fur_dual_sigma_node((_e35 + uvec3(1u)));
    vec3 hi_3 = sqrt(_e39);
    w_3 = clamp(((sqrt(s_3) - lo_4) / (hi_3 - lo_4)), vec3(0.0), vec3(1.0));
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
    uint k_18 = min(uint(_e17), 62u);
    float _e21 = t_8;
    return FurLoc(k_18, (_e21 - float(k_18)));
}

vec3 fur_dual_node(uvec3 a_5, uint k_11, uint f_3) {
    vec3 _e6 = fur_dual_rgb(a_5, ((k_11 * FUR_DUAL_FIELDS) + f_3));
    return _e6;
}

vec3 fur_dual_field(FurLoc l_4, uint f_4) {
    uvec3 lo_5 = fur_dual_at.node;
    vec3 _e6 = fur_dual_node(lo_5, l_4.i, f_4);
    vec3 _e10 = fur_dual_node(lo_5, (l_4.i + 1u), f_4);
    vec3 _e15 = fur_dual_node((lo_5 + uvec3(1u)), l_4.i, f_4);
    vec3 _e22 = fur_dual_node((lo_5 + uvec3(1u)), (l_4.i + 1u), f_4);
    vec3 v0_8 = (_e6 + ((_e10 - _e6) * l_4.w));
    vec3 v1_8 = (_e15 + ((_e22 - _e15) * l_4.w));
    vec3 _e34 = fur_dual_at.w;
    return (v0_8 + ((v1_8 - v0_8) * _e34));
}

vec3 fur_dual_ng_at(uvec3 a_6, uint g_5, FurLoc l_5, FurLoc p) {
    uint row0_ = ((((g_5 * FUR_DUAL_THETA_NODES) + l_5.i) * FUR_DUAL_PHI_NODES) + p.i);
    uint row1_ = (row0_ + FUR_DUAL_PHI_NODES);
    vec3 _e16 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row0_));
    vec3 _e21 = fur_dual_rgb(a_6, ((FUR_DUAL_NG_START + row0_) + 1u));
    vec3 _e24 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row1_));
    vec3 _e29 = fur_dual_rgb(a_6, ((FUR_DUAL_NG_START + row1_) + 1u));
    float w_5 = l_5.w;
    float v_4 = p.w;
    return ((((((1.0 - w_5) * (1.0 - v_4)) * _e16) + (((1.0 - w_5) * v_4) * _e21)) + ((w_5 * (1.0 - v_4)) * _e24)) + ((w_5 * v_4) * _e29));
}

vec3 fur_dual_ng(uint g_6, FurLoc l_6, FurLoc p_1) {
    uvec3 _e5 = fur_dual_at.node;
    vec3 _e6 = fur_dual_ng_at(_e5, g_6, l_6, p_1);
    uvec3 _e9 = fur_dual_at.node;
    vec3 _e13 = fur_dual_ng_at((_e9 + uvec3(1u)), g_6, l_6, p_1);
    vec3 _e17 = fur_dual_at.w;
    return (_e6 + ((_e13 - _e6) * _e17));
}

vec3 fur_rsqrt_newton(vec3 v_1) {
    vec3 y_2 = vec3(0.0);
    y_2 = uintBitsToFloat((uvec3(1597463174u) - (floatBitsToUint(v_1) >> uvec3(1u))));
    vec3 h_3 = (0.5 * v_1);
    vec3 _e12 = y_2;
    vec3 _e13 = y_2;
    vec3 _e15 = y_2;
    y_2 = (_e12 * (vec3(1.5) - ((h_3 * _e13) * _e15)));
    vec3 _e21 = y_2;
    vec3 _e22 = y_2;
    vec3 _e24 = y_2;
    y_2 = (_e21 * (vec3(1.5) - ((h_3 * _e22) * _e24)));
    vec3 _e30 = y_2;
    vec3 _e31 = y_2;
    vec3 _e33 = y_2;
    return (_e30 * (vec3(1.5) - ((h_3 * _e31) * _e33)));
}

vec3 fur_exp_neg(vec3 x_in) {
    vec3 p_2 = vec3(0.00019875693);
    vec3 x_17 = min(max(x_in, vec3(0.0)), vec3(87.0));
    vec3 k_19 = roundEven((x_17 * FUR_LOG2_E));
    vec3 r_15 = (((k_19 * FUR_LN2_HI) - x_17) + (k_19 * FUR_LN2_LO));
    vec3 z_1 = (r_15 * r_15);
    vec3 _e20 = p_2;
    p_2 = ((_e20 * r_15) + vec3(0.0013981999));
    vec3 _e25 = p_2;
    p_2 = ((_e25 * r_15) + vec3(0.008333452));
    vec3 _e30 = p_2;
    p_2 = ((_e30 * r_15) + vec3(0.041665796));
    vec3 _e35 = p_2;
    p_2 = ((_e35 * r_15) + vec3(0.16666666));
    vec3 _e40 = p_2;
    p_2 = ((_e40 * r_15) + vec3(0.5));
    vec3 _e45 = p_2;
    vec3 e = (((_e45 * z_1) + r_15) + vec3(1.0));
    return mix(ldexp(e, -(ivec3(k_19))), vec3(0.0), greaterThan(x_in, vec3(87.0)));
}

vec3 fur_erf(vec3 x_11) {
    bvec3 _e7 = fur_is_nan3_(x_11);
    vec3 a_10 = mix(min(abs(x_11), vec3(10.0)), vec3(0.0), _e7);
    vec3 p_6 = ((((((((((((FUR_ERF_A6_ * a_10) + vec3(0.0002765672)) * a_10) + vec3(0.0001520143)) * a_10) + vec3(0.009270527)) * a_10) + vec3(0.04228201)) * a_10) + vec3(0.07052308)) * a_10) + vec3(1.0));
    vec3 p2_ = (p_6 * p_6);
    vec3 p4_ = (p2_ * p2_);
    vec3 p8_ = (p4_ * p4_);
    vec3 e_1 = (vec3(1.0) - (vec3(1.0) / (p8_ * p8_)));
    uvec3 sign_ = (floatBitsToUint(x_11) & uvec3(2147483648u));
    return uintBitsToFloat((floatBitsToUint(e_1) | sign_));
}

vec3 fur_dual_between(vec3 x_12, vec3 top) {
    bvec3 _e8 = fur_is_nan3_(x_12);
    return mix(min(max(x_12, vec3(0.0)), top), vec3(0.0), _e8);
}

vec3 fur_dual_gauss(vec3 d_6, vec3 v_in, float theta_i_5) {
    vec3 v_5 = clamp(v_in, vec3(3e-6), vec3(1e30));
    vec3 _e8 = fur_rsqrt_newton(v_5);
    vec3 z_2 = (d_6 * _e8);
    vec3 _e13 = fur_exp_neg(((0.5 * z_2) * z_2));
    vec3 g_8 = ((_e13 * _e8) * FUR_INV_SQRT_TAU);
    vec3 centre = (((d_6 - vec3(theta_i_5)) * _e8) * FUR_FRAC_1_SQRT_2_);
    vec3 half_range = ((FUR_HALF_PI * _e8) * FUR_FRAC_1_SQRT_2_);
    vec3 _e27 = fur_erf((centre + half_range));
    vec3 _e29 = fur_erf((centre - half_range));
    vec3 mass = (0.5 * (_e27 - _e29));
    return (g_8 / max(mass, vec3(0.05)));
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

vec3 fur_dual_coat_node(uvec3 n_1, uint k_13) {
    vec3 _e3 = fur_dual_node(n_1, k_13, FUR_DUAL_LOG2_DECAY);
    vec3 _e5 = fur_dual_node(n_1, k_13, FUR_DUAL_A_F2_);
    vec3 a_11 = clamp(_e5, vec3(0.0), vec3(1.0));
    vec3 _e12 = fur_dual_power(_e3, 1.0);
    vec3 _e16 = fur_rsqrt_newton(max(a_11, vec3(1e-30)));
    vec3 t_13 = (a_11 * _e16);
    vec3 _e18 = fur_reflectance_squared(_e12, t_13);
    return _e18;
}

vec3 fur_dual_coat(FurLoc l_7) {
    uvec3 lo_6 = fur_dual_at.node;
    vec3 _e5 = fur_dual_coat_node(lo_6, l_7.i);
    vec3 _e9 = fur_dual_coat_node(lo_6, (l_7.i + 1u));
    vec3 _e14 = fur_dual_coat_node((lo_6 + uvec3(1u)), l_7.i);
    vec3 _e21 = fur_dual_coat_node((lo_6 + uvec3(1u)), (l_7.i + 1u));
    vec3 rho0_ = (_e5 + ((_e9 - _e5) * l_7.w));
    vec3 rho1_ = (_e14 + ((_e21 - _e14) * l_7.w));
    vec3 _e33 = fur_dual_at.w;
    return (rho0_ + ((rho1_ - rho0_) * _e33));
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

vec3 fur_eval_dual(float theta_i_6, float theta_r_8, float phi_in_1, float fibers, float fibers_below, float d_f_in, float d_b_in, vec3 sigma_ca_6) {
    vec3 out_4 = vec3(0.0);
    float p_3 = 0.0;
    vec3 f_s = vec3(0.0);
    uint g_7 = 0u;
    FurDualColour _e9 = fur_dual_locate(sigma_ca_6);
    fur_dual_at = _e9;
    vec3 zero = vec3(0.0);
    bool _e12 = fur_valid(theta_i_6, theta_r_8, phi_in_1);
    if (!(_e12)) {
        return zero;
    }
    float _e15 = fur_dual_clean(fibers, FUR_DUAL_MAX_FIBERS);
    float _e16 = fur_dual_below(fibers_below);
    float _e18 = fur_dual_clean(d_f_in, FUR_DUAL_MAX_DENSITY);
    float _e20 = fur_dual_clean(d_b_in, FUR_DUAL_MAX_DENSITY);
    float x_18 = (theta_i_6 + theta_r_8);
    float _e22 = fur_cos_within_half_pi(theta_i_6);
    float inv_cos2_ = (1.0 / max((_e22 * _e22), FUR_MIN_COS2_));
    float direct = clamp((1.0 - _e15), 0.0, 1.0);
    FurLoc _e33 = fur_dual_theta(theta_r_8);
    float _e34 = fur_wrap_angle(phi_in_1);
    float abs_phi = abs(_e34);
    vec3 _e41 = fur_dual_field(_e33, ((abs_phi < FUR_HALF_PI) ? FUR_DUAL_BACK : FUR_DUAL_FRONT));
    vec3 _e43 = fur_dual_field(_e33, FUR_DUAL_LOG2_DECAY);
    vec3 _e45 = fur_dual_field(_e33, FUR_DUAL_A_F2_);
    vec3 _e47 = fur_dual_power(_e43, 1.0);
    vec3 _e50 = fur_dual_power(_e43, (2.0 * _e16));
    vec3 _e51 = fur_dual_coat(_e33);
    vec3 _e52 = fur_backscatter_factor(_e51, _e47, _e50);
    vec3 half_energy = (_e41 * _e52);
    vec3 _e55 = fur_dual_field(_e33, FUR_DUAL_SIGMA_B0_);
    vec3 _e57 = fur_dual_field(_e33, FUR_DUAL_DELTA_B);
    vec3 d_back = (vec3(x_18) - _e57);
    vec3 s_b = ((vec3(1.0) + (_e20 * _e45)) * _e55);
    vec3 v_back = (s_b * s_b);
    float back_scale = ((_e20 * inv_cos2_) / FUR_PI);
    out_4 = zero;
    if ((direct > 0.0)) {
        vec3 _e74 = fur_dual_gauss(d_back, v_back, theta_i_6);
        out_4 = (((direct * back_scale) * half_energy) * _e74);
    }
    if ((_e15 > 0.0)) {
        FurLoc _e79 = fur_dual_theta(-(theta_i_6));
        vec3 _e81 = fur_dual_field(_e79, FUR_DUAL_LOG2_DECAY);
        vec3 _e83 = fur_dual_field(_e79, FUR_DUAL_BETA_F);
        vec3 _e84 = fur_dual_power(_e81, _e15);
        vec3 _e87 = fur_dual_power(_e81, (2.0 * _e16));
        vec3 _e88 = fur_dual_coat(_e79);
        vec3 _e89 = fur_downward_flux(_e84, _e87, _e88);
        vec3 spread = (max((_e89 - vec3(direct)), zero) * _e18);
        if (any(greaterThan(spread, zero))) {
            vec3 s2f = ((_e15 * _e83) * _e83);
            p_3 = (abs_phi * FUR_DUAL_PHI_SCALE);
            float _e101 = p_3;
            float _e104 = p_3;
            p_3 = ((_e104 > 0.0) ? min(_e101, 31.0) : 0.0);
            float _e109 = p_3;
            uint j_7 = min(uint(_e109), 30u);
            float _e113 = p_3;
            FurLoc at_phi = FurLoc(j_7, (_e113 - float(j_7)));
            f_s = zero;
            bool loop_init_4 = true;
            while(true) {
                if (!loop_init_4) {
                    uint _e141 = g_7;
                    g_7 = (_e141 + 1u);
                }
                loop_init_4 = false;
                uint _e120 = g_7;
                if ((_e120 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e124 = g_7;
                    vec3 _e126 = fur_dual_field(_e33, (FUR_DUAL_MEAN + _e124));
                    uint _e128 = g_7;
                    vec3 _e130 = fur_dual_field(_e33, (FUR_DUAL_SD + _e128));
                    uint _e131 = g_7;
                    vec3 _e132 = fur_dual_ng(_e131, _e33, at_phi);
                    vec3 v_6 = ((_e130 * _e130) + s2f);
                    vec3 _e135 = f_s;
                    vec3 _e138 = fur_dual_gauss((vec3(x_18) - _e126), v_6, theta_i_6);
                    f_s = (_e135 + (_e132 * _e138));
                }
            }
            vec3 _e145 = fur_dual_gauss(d_back, (v_back + s2f), theta_i_6);
            vec3 _e146 = out_4;
            vec3 _e147 = f_s;
            out_4 = (_e146 + (spread * ((_e147 * inv_cos2_) + ((back_scale * half_energy) * _e145))));
        }
    }
    float _e155 = out_4.x;
    bool _e156 = fur_finite(_e155);
    float _e158 = out_4.y;
    bool _e159 = fur_finite(_e158);
    float _e161 = out_4.z;
    bool _e162 = fur_finite(_e161);
    bvec3 finite = bvec3(_e156, _e159, _e162);
    vec3 _e164 = out_4;
    vec3 _e165 = out_4;
    return mix(zero, _e164, bvec3(finite.x && greaterThan(_e165, zero).x, finite.y && greaterThan(_e165, zero).y, finite.z && greaterThan(_e165, zero).z));
}

vec3 fur_eval_dual_dirs(vec3 wi_2, vec3 wr_2, vec3 u_6, float fibers_1, float fibers_below_1, float d_f_1, float d_b, vec3 sigma_ca_7) {
    FurDirAngles _e8 = fur_angles_from_dirs(wi_2, wr_2, u_6);
    if (!(_e8.ok)) {
        return vec3(0.0);
    }
    vec3 _e16 = fur_eval_dual(_e8.theta_i, _e8.theta_r, _e8.phi, fibers_1, fibers_below_1, d_f_1, d_b, sigma_ca_7);
    return _e16;
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
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e51 = k_14;
            k_14 = (_e51 + 1u);
        }
        loop_init_5 = false;
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
            float lo_7 = nodes_2[((_e22 + 1u) / 4u)][((_e28 + 1u) % 4u)];
            if ((c_2 >= lo_7)) {
                t_10 = 0.0;
                if ((hi_4 > lo_7)) {
                    t_10 = ((hi_4 - c_2) / (hi_4 - lo_7));
                }
                uint _e42 = k_14;
                float _e44 = t_10;
                float x_19 = (((float(_e42) + _e44) / 23.0) * FUR_COAT_AXIS_END);
                float _e50 = fur_coat_sigma_at(x_19);
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
    uint base = (16u * q);
    vec3 parts[5] = vec3[5](f_5.r, f_5.tt, f_5.trt, f_5.scattered, f_5.total);
    bool loop_init_6 = true;
    while(true) {
        if (!loop_init_6) {
            uint _e46 = k_15;
            k_15 = (_e46 + 1u);
        }
        loop_init_6 = false;
        uint _e12 = k_15;
        if ((_e12 < 5u)) {
        } else {
            break;
        }
        {
            uint _e17 = k_15;
            uint _e21 = k_15;
            _group_0_binding_2_cs[(base + (3u * _e17))] = parts[_e21].x;
            uint _e26 = k_15;
            uint _e32 = k_15;
            _group_0_binding_2_cs[((base + (3u * _e26)) + 1u)] = parts[_e32].y;
            uint _e37 = k_15;
            uint _e43 = k_15;
            _group_0_binding_2_cs[((base + (3u * _e37)) + 2u)] = parts[_e43].z;
        }
    }
    _group_0_binding_2_cs[(base + 15u)] = 0.0;
    return;
}

void fur_store_rgb(uint q_1, vec3 v_2) {
    uint k_16 = 3u;
    uint base_1 = (16u * q_1);
    _group_0_binding_2_cs[base_1] = v_2.x;
    _group_0_binding_2_cs[(base_1 + 1u)] = v_2.y;
    _group_0_binding_2_cs[(base_1 + 2u)] = v_2.z;
    bool loop_init_7 = true;
    while(true) {
        if (!loop_init_7) {
            uint _e27 = k_16;
            k_16 = (_e27 + 1u);
        }
        loop_init_7 = false;
        uint _e19 = k_16;
        if ((_e19 < 16u)) {
        } else {
            break;
        }
        {
            uint _e23 = k_16;
            _group_0_binding_2_cs[(base_1 + _e23)] = 0.0;
        }
    }
    return;
}

void main() {
    uvec3 id_5 = gl_GlobalInvocationID;
    uint q_2 = id_5.x;
    if ((((4u * q_2) + 3u) >= uint(_group_0_binding_1_cs.length()))) {
        return;
    }
    vec4 wi_3 = _group_0_binding_1_cs[(4u * q_2)];
    vec4 wr_3 = _group_0_binding_1_cs[((4u * q_2) + 1u)];
    vec4 u_9 = _group_0_binding_1_cs[((4u * q_2) + 2u)];
    vec4 below = _group_0_binding_1_cs[((4u * q_2) + 3u)];
    vec3 _e43 = fur_eval_dual_dirs(wi_3.xyz, wr_3.xyz, u_9.xyz, wi_3.w, below.x, wr_3.w, u_9.w, below.yzw);
    fur_store_rgb(q_2, _e43);
    return;
}

