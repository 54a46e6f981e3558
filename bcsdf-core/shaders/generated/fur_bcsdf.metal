// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size3;
    uint size4;
};

typedef uint type_1[1];
struct FurFamilies {
    metal::float3 r;
    metal::float3 tt;
    metal::float3 trt;
    metal::float3 scattered;
    metal::float3 total;
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
    metal::uint3 plane;
    metal::float3 w0_;
    metal::float3 w1_;
    metal::float3 w2_;
};
struct type_7 {
    float inner[3];
};
struct type_8 {
    float inner[2];
};
struct type_9 {
    float inner[12];
};
struct type_10 {
    float inner[4];
};
struct FurLookups {
    type_7 m;
    type_8 ms;
    type_9 n;
    type_10 n0_;
    float front;
    float inv_cos2_;
};
struct FurDensity {
    uint prefix_at;
    uint entries;
    uint nodes;
    uint rows;
    float step;
    uint block;
    uint table;
    uint channel;
};
struct type_11 {
    float inner[6];
};
struct type_12 {
    uint inner[6];
};
struct type_13 {
    metal::float3 inner[4];
};
struct FurDirAngles {
    float theta_i;
    float theta_r;
    float phi;
    bool ok;
    char _pad4[3];
};
struct FurSample {
    float theta_i;
    float phi;
    float pdf;
    char _pad3[4];
    metal::packed_float3 weight;
    uint family;
    bool ok;
    char _pad6[15];
};
struct type_14 {
    uint inner[3];
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
    metal::float4 s;
};
struct FurMAt {
    metal::float3 cdf;
    metal::float3 value;
};
struct type_17 {
    float inner[5];
};
struct type_18 {
    FurRange inner[5];
};
struct FurParts {
    type_17 a;
    char _pad1[12];
    type_18 ranges;
};
struct FurDualColour {
    metal::uint3 node;
    metal::float3 w;
};
struct type_19 {
    metal::float4 inner[6];
};
typedef metal::float4 type_20[1];
typedef float type_21[1];
struct type_22 {
    metal::float3 inner[5];
};
constant float FUR_PI = 3.1415927;
constant float FUR_HALF_PI = 1.5707964;
constant float FUR_TAU = 6.2831855;
constant float FUR_MIN_COS2_ = 0.0001;
constant float FUR_POLE_SLIVER = 0.010000167;
constant uint FUR_HEADER_HALVES = 84u;
constant uint FUR_N_ABS_WORD = 9u;
constant uint FUR_SCALE_WORD = 10u;
constant uint FUR_ABS_SCALE_WORD = 39u;
constant float FUR_SIGMA_CA_MAX = 1000.0;
constant float FUR_ROOT_RATE = 8.325476;
constant float FUR_ROOT_SHARE = 0.4;
constant float FUR_LOG2_E = 1.442695;
constant uint FUR_CLOSURE_WORD = 27u;
constant uint FUR_DUAL_HEADER_WORDS = 20u;
constant uint FUR_DUAL_ABS_NODES = 16u;
constant uint FUR_DUAL_NODE_HALVES = 9152u;
constant float FUR_DUAL_KNEE = 3.0;
constant float FUR_DUAL_SIGMA_MAX = 1000.0;
constant uint FUR_DUAL_FIELDS = 15u;
constant uint FUR_DUAL_LOG2_DECAY = 0u;
constant uint FUR_DUAL_BETA_F = 1u;
constant uint FUR_DUAL_BACK = 2u;
constant uint FUR_DUAL_FRONT = 3u;
constant uint FUR_DUAL_DELTA_B = 4u;
constant uint FUR_DUAL_SIGMA_B0_ = 5u;
constant uint FUR_DUAL_A_F2_ = 6u;
constant uint FUR_DUAL_MEAN = 7u;
constant uint FUR_DUAL_SD = 11u;
constant uint FUR_DUAL_THETA_NODES = 64u;
constant uint FUR_DUAL_PHI_NODES = 32u;
constant uint FUR_DUAL_NG_START = 960u;
constant float FUR_DUAL_THETA_SCALE = 20.371832;
constant float FUR_DUAL_PHI_SCALE = 9.867606;
constant float FUR_DUAL_MAX_FIBERS = 1000000.0;
constant float FUR_DUAL_MAX_DENSITY = 4.0;
constant float FUR_DUAL_MIN_VARIANCE = 0.000003;
constant float FUR_DUAL_LINE_SAMPLE_OFFSET = 1.0;
constant float FUR_DUAL_MIN_MASS = 0.05;
constant float FUR_DUAL_TINY = 0.000001;
constant float FUR_LN2_ = 0.6931472;
constant float FUR_LN2_HI = 0.6933594;
constant float FUR_LN2_LO = -0.00021219444;
constant float FUR_INV_SQRT_TAU = 0.3989423;
constant float FUR_FRAC_1_SQRT_2_ = 0.70710677;
constant float FUR_ERF_A1_ = 0.07052308;
constant float FUR_ERF_A2_ = 0.04228201;
constant float FUR_ERF_A3_ = 0.009270527;
constant float FUR_ERF_A4_ = 0.0001520143;
constant float FUR_ERF_A5_ = 0.0002765672;
constant float FUR_ERF_A6_ = 0.0000430638;
constant float FUR_DUAL_DIFFUSIVITY = 2.0;
constant uint FUR_COAT_NODES = 24u;
constant float FUR_COAT_AXIS_END = 0.9995004;

FurAxis fur_axis(
    bool centred,
    float inv_span,
    uint nodes
) {
    float last_1 = static_cast<float>(nodes - 1u);
    return FurAxis {last_1 * inv_span, centred ? (0.5 * last_1) : 0.0, last_1, nodes};
}

int naga_f2i32(float value) {
    return static_cast<int>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

FurLoc fur_locate(
    FurAxis a,
    float x
) {
    float u_7 = metal::min(metal::max((x * a.inv_step) + a.offset, 0.0), a.last);
    int i_1 = metal::min(naga_f2i32(u_7), as_type<int>(as_type<uint>(static_cast<int>(a.nodes)) - as_type<uint>(2)));
    return FurLoc {static_cast<uint>(i_1), u_7 - static_cast<float>(i_1)};
}

uint fur_word(
    uint k,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = fur_lut[k];
    return _e3;
}

float fur_half(
    uint h,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint word = fur_lut[h >> 1u];
    uint bits = ((h & 1u) == 1u) ? (word >> 16u) : (word & 65535u);
    return as_type<float>(bits << 13u);
}

float fur_unbias(
    uint t,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = fur_word(FUR_SCALE_WORD + t, fur_lut, _buffer_sizes);
    return as_type<float>(_e3) * as_type<float>(2004877312u);
}

uint fur_n_plane_halves(
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e2 = fur_word(6u, fur_lut, _buffer_sizes);
    uint _e5 = fur_word(5u, fur_lut, _buffer_sizes);
    return (4u * _e2) * _e5;
}

metal::bool3 fur_is_nan3_(
    metal::float3 x_1
) {
    return (as_type<metal::uint3>(x_1) & metal::uint3(2147483647u)) > metal::uint3(2139095040u);
}

metal::int3 naga_f2i32(metal::float3 value) {
    return static_cast<metal::int3>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

metal::int3 naga_neg(metal::int3 val) {
    return as_type<metal::int3>(-as_type<metal::uint3>(val));
}

metal::float3 fur_pow2_neg(
    metal::float3 y_in
) {
    metal::bool3 _e9 = fur_is_nan3_(y_in);
    metal::float3 y_3 = metal::select(metal::min(metal::max(y_in, metal::float3(0.0)), metal::float3(125.0)), metal::float3(0.0), _e9);
    metal::float3 k_17 = metal::rint(y_3);
    metal::float3 f_6 = k_17 - y_3;
    metal::float3 f2_ = f_6 * f_6;
    metal::float3 f4_ = f2_ * f2_;
    metal::float3 p01_ = (0.000015252734 * f_6) + metal::float3(0.0001540353);
    metal::float3 p23_ = (0.0013333558 * f_6) + metal::float3(0.009618129);
    metal::float3 p45_ = (0.05550411 * f_6) + metal::float3(0.2402265);
    metal::float3 p67_ = (0.6931472 * f_6) + metal::float3(1.0);
    metal::float3 p_4 = (((p01_ * f2_) + p23_) * f4_) + ((p45_ * f2_) + p67_);
    return metal::ldexp(p_4, naga_neg(naga_f2i32(k_17)));
}

metal::uint3 naga_f2u32(metal::float3 value) {
    return static_cast<metal::uint3>(metal::clamp(value, 0.0, 4294967000.0));
}

FurColour fur_locate_colour(
    metal::float3 sigma_ca,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e2 = fur_word(FUR_N_ABS_WORD, fur_lut, _buffer_sizes);
    float last_2 = static_cast<float>(_e2 - 1u);
    uint _e7 = fur_word(FUR_ABS_SCALE_WORD, fur_lut, _buffer_sizes);
    float scale = as_type<float>(_e7);
    metal::bool3 _e17 = fur_is_nan3_(sigma_ca);
    metal::float3 s_1 = metal::select(metal::min(metal::max(sigma_ca, metal::float3(0.0)), metal::float3(1000.0)), metal::float3(0.0), _e17);
    metal::float3 _e23 = fur_pow2_neg(metal::sqrt(s_1 * FUR_ROOT_RATE));
    metal::float3 _e30 = fur_pow2_neg((s_1 / metal::float3(scale)) * FUR_LOG2_E);
    metal::float3 e = (FUR_ROOT_SHARE * _e23) + (0.6 * _e30);
    metal::float3 x_16 = metal::min(metal::float3(1.0) - e, metal::float3(1.0));
    metal::float3 u_8 = metal::clamp(x_16 * last_2, metal::float3(0.0), metal::float3(last_2));
    metal::uint3 k_18 = metal::min(naga_f2u32(u_8), metal::uint3(_e2 - 3u));
    metal::float3 t_11 = u_8 - static_cast<metal::float3>(k_18);
    metal::float3 w0_ = (0.5 * (t_11 - metal::float3(1.0))) * (t_11 - metal::float3(2.0));
    metal::float3 w1_ = t_11 * (metal::float3(2.0) - t_11);
    metal::float3 w2_ = (0.5 * t_11) * (t_11 - metal::float3(1.0));
    uint _e71 = fur_word(6u, fur_lut, _buffer_sizes);
    uint _e73 = fur_word(5u, fur_lut, _buffer_sizes);
    return FurColour {k_18 * (_e71 * _e73), w0_, w1_, w2_};
}

float fur_cos_within_half_pi(
    float x_2
) {
    float acc = -0.0000002755732;
    float acc_1 = 0.0000027557319;
    float a_7 = metal::abs(x_2);
    if (a_7 <= 0.7853982) {
        float y_4 = a_7 * a_7;
        float _e7 = acc;
        acc = (_e7 * y_4) + 0.000024801588;
        float _e11 = acc;
        acc = (_e11 * y_4) - 0.0013888889;
        float _e15 = acc;
        acc = (_e15 * y_4) + 0.041666668;
        float _e19 = acc;
        acc = (_e19 * y_4) - 0.5;
        float _e23 = acc;
        return (_e23 * y_4) + 1.0;
    }
    float r_13 = (1.5707964 - a_7) + ((a_7 > 4.0) ? 0.0 : -0.00000004371139);
    float y_5 = r_13 * r_13;
    float _e38 = acc_1;
    acc_1 = (_e38 * y_5) - 0.0001984127;
    float _e42 = acc_1;
    acc_1 = (_e42 * y_5) + 0.008333334;
    float _e46 = acc_1;
    acc_1 = (_e46 * y_5) - 0.16666667;
    float _e50 = acc_1;
    return ((_e50 * y_5) * r_13) + r_13;
}

float fur_wrap_angle(
    float x_3
) {
    bool local = {};
    bool local_1 = {};
    bool local_2 = {};
    float y = {};
    bool local_3 = {};
    if (x_3 > -3.1415927) {
        local = x_3 <= FUR_PI;
    } else {
        local = false;
    }
    bool _e8 = local;
    if (_e8) {
        return x_3;
    }
    if (x_3 > FUR_PI) {
        local_1 = x_3 <= 9.424778;
    } else {
        local_1 = false;
    }
    bool _e16 = local_1;
    if (_e16) {
        return x_3 - FUR_TAU;
    }
    if (x_3 <= -3.1415927) {
        local_2 = x_3 > -9.424778;
    } else {
        local_2 = false;
    }
    bool _e26 = local_2;
    if (_e26) {
        return x_3 + FUR_TAU;
    }
    y = x_3 - (FUR_TAU * metal::floor((x_3 + FUR_PI) / FUR_TAU));
    float _e38 = y;
    if (_e38 <= -3.1415927) {
        float _e41 = y;
        y = _e41 + FUR_TAU;
    }
    float _e44 = y;
    if (_e44 > FUR_PI) {
        float _e47 = y;
        y = _e47 - FUR_TAU;
    }
    float _e50 = y;
    if (_e50 > -3.1415927) {
        float _e55 = y;
        local_3 = _e55 <= FUR_PI;
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

FurFamilies fur_zero(
) {
    metal::float3 z = metal::float3(0.0);
    return FurFamilies {z, z, z, z, z};
}

bool fur_finite(
    float x_4
) {
    return (as_type<uint>(x_4) & 2139095040u) != 2139095040u;
}

bool fur_valid(
    float theta_i,
    float theta_r,
    float phi
) {
    bool local_4 = {};
    bool local_5 = {};
    bool local_6 = {};
    bool local_7 = {};
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
        local_6 = metal::abs(theta_i) <= FUR_HALF_PI;
    } else {
        local_6 = false;
    }
    bool _e20 = local_6;
    if (_e20) {
        local_7 = metal::abs(theta_r) <= FUR_HALF_PI;
    } else {
        local_7 = false;
    }
    bool _e27 = local_7;
    return _e27;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

uint fur_entries(
    uint nodes_1,
    uint block
) {
    return naga_div(((nodes_1 - 1u) + block) - 1u, block) + 1u;
}

FurDensity fur_density(
    uint d,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint at = {};
    uint _e2 = fur_word(4u, fur_lut, _buffer_sizes);
    uint _e4 = fur_word(5u, fur_lut, _buffer_sizes);
    uint _e6 = fur_word(6u, fur_lut, _buffer_sizes);
    uint _e8 = fur_word(7u, fur_lut, _buffer_sizes);
    uint _e10 = fur_word(8u, fur_lut, _buffer_sizes);
    uint _e13 = fur_n_plane_halves(fur_lut, _buffer_sizes);
    uint _e15 = fur_word(FUR_N_ABS_WORD, fur_lut, _buffer_sizes);
    uint values = ((3u * _e2) + (_e13 * _e15)) + ((2u * _e8) * _e10);
    at = 168u + (2u * values);
    uint _e28 = fur_entries(_e2, 1u);
    uint _e30 = fur_entries(_e6, 8u);
    uint _e32 = fur_entries(_e8, 8u);
    if (d < 3u) {
        uint _e35 = at;
        return FurDensity {_e35 + ((4u * d) * _e28), _e28, _e2, 1u, 6.2831855 / static_cast<float>(_e2 - 1u), 1u, 0u, d};
    }
    uint _e49 = at;
    at = _e49 + (12u * _e28);
    if (d < 7u) {
        uint f_7 = d - 3u;
        uint _e57 = at;
        return FurDensity {_e57 + (((4u * f_7) * _e4) * _e30), _e30, _e6, _e4, FUR_PI / static_cast<float>(_e6 - 1u), 8u, 1u, f_7};
    }
    uint _e71 = at;
    at = _e71 + ((16u * _e4) * _e30);
    if (d < 9u) {
        uint x_17 = d - 7u;
        uint _e80 = at;
        return FurDensity {_e80 + (((4u * x_17) * _e10) * _e32), _e32, _e8, _e10, FUR_PI / static_cast<float>(_e8 - 1u), 8u, 2u, x_17};
    }
    uint _e94 = at;
    at = _e94 + ((8u * _e10) * _e32);
    uint _e99 = at;
    return FurDensity {_e99, _e30, _e6, _e4, FUR_PI / static_cast<float>(_e6 - 1u), 8u, 1u, 3u};
}

uint fur_norm_start(
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurDensity _e1 = fur_density(9u, fur_lut, _buffer_sizes);
    return _e1.prefix_at + ((4u * _e1.rows) * _e1.entries);
}

float fur_f32_at(
    uint byte,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint w_4 = byte >> 2u;
    if ((byte & 3u) == 0u) {
        uint _e9 = fur_lut[w_4];
        return as_type<float>(_e9);
    }
    uint _e13 = fur_lut[w_4];
    uint _e20 = fur_lut[w_4 + 1u];
    return as_type<float>((_e13 >> 16u) | (_e20 << 16u));
}

metal::float3 fur_sphere_norms(
    float theta_r_1,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 out = metal::float3(0.0);
    uint g = 0u;
    uint _e2 = fur_word(FUR_CLOSURE_WORD, fur_lut, _buffer_sizes);
    if (_e2 != 1u) {
        return metal::float3(1.0);
    }
    uint _e10 = fur_word(4u, fur_lut, _buffer_sizes);
    FurAxis _e11 = fur_axis(true, 0.31830987, _e10);
    FurLoc _e12 = fur_locate(_e11, theta_r_1);
    uint _e13 = fur_norm_start(fur_lut, _buffer_sizes);
    uint at_1 = _e13 + (12u * _e12.i);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e44 = g;
            g = _e44 + 1u;
        }
        loop_init = false;
        uint _e23 = g;
        if (_e23 < 3u) {
        } else {
            break;
        }
        {
            uint _e27 = g;
            float _e30 = fur_f32_at(at_1 + (4u * _e27), fur_lut, _buffer_sizes);
            uint _e31 = g;
            uint _e36 = g;
            float _e39 = fur_f32_at((at_1 + 12u) + (4u * _e36), fur_lut, _buffer_sizes);
            out[_e31] = _e30 + ((_e39 - _e30) * _e12.w);
        }
    }
    metal::float3 _e47 = out;
    return _e47;
}

FurLookups fur_lookups(
    float theta_i_1,
    float theta_r_2,
    float phi_in,
    metal::float3 sigma_ca_1,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_7 m = {};
    uint ch = 0u;
    uint ch_1 = 0u;
    type_8 ms = {};
    uint ch_2 = 0u;
    type_9 n = {};
    uint c = 0u;
    uint f = {};
    float left = {};
    float right = {};
    uint i = {};
    type_10 nl = {};
    uint f_1 = 0u;
    float _e4 = fur_wrap_angle(phi_in);
    uint _e6 = fur_word(4u, fur_lut, _buffer_sizes);
    uint _e8 = fur_word(5u, fur_lut, _buffer_sizes);
    uint _e10 = fur_word(6u, fur_lut, _buffer_sizes);
    uint _e12 = fur_word(7u, fur_lut, _buffer_sizes);
    uint _e14 = fur_word(8u, fur_lut, _buffer_sizes);
    uint n0_ = FUR_HEADER_HALVES + (3u * _e6);
    uint _e19 = fur_n_plane_halves(fur_lut, _buffer_sizes);
    uint _e21 = fur_word(FUR_N_ABS_WORD, fur_lut, _buffer_sizes);
    uint s0_ = n0_ + (_e19 * _e21);
    float abs_phi = metal::abs(_e4);
    float _e25 = fur_cos_within_half_pi(theta_i_1);
    float inv_cos2_ = 1.0 / metal::max(_e25 * _e25, FUR_MIN_COS2_);
    FurAxis _e33 = fur_axis(true, 0.15915494, _e6);
    FurLoc _e35 = fur_locate(_e33, theta_i_1 + theta_r_2);
    float _e37 = fur_unbias(0u, fur_lut, _buffer_sizes);
    float wm0_ = (1.0 - _e35.w) * _e37;
    float wm1_ = _e35.w * _e37;
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e71 = ch;
            ch = _e71 + 1u;
        }
        loop_init_1 = false;
        uint _e47 = ch;
        if (_e47 < 3u) {
        } else {
            break;
        }
        {
            uint _e54 = ch;
            float _e56 = fur_half((FUR_HEADER_HALVES + (3u * _e35.i)) + _e54, fur_lut, _buffer_sizes);
            uint _e63 = ch;
            float _e65 = fur_half((FUR_HEADER_HALVES + (3u * (_e35.i + 1u))) + _e63, fur_lut, _buffer_sizes);
            uint _e66 = ch;
            m.inner[_e66] = (wm0_ * _e56) + (wm1_ * _e65);
        }
    }
    metal::float3 _e74 = fur_sphere_norms(theta_r_2, fur_lut, _buffer_sizes);
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_2 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_2) {
            uint _e88 = ch_1;
            ch_1 = _e88 + 1u;
        }
        loop_init_2 = false;
        uint _e77 = ch_1;
        if (_e77 < 3u) {
        } else {
            break;
        }
        {
            uint _e80 = ch_1;
            uint _e82 = ch_1;
            float _e84 = m.inner[_e82];
            uint _e85 = ch_1;
            m.inner[_e80] = _e84 * _e74[_e85];
        }
    }
    FurAxis _e93 = fur_axis(true, 0.31830987, _e14);
    FurLoc _e94 = fur_locate(_e93, theta_r_2);
    FurAxis _e97 = fur_axis(true, 0.31830987, _e12);
    FurLoc _e98 = fur_locate(_e97, theta_i_1);
    float _e100 = fur_unbias(2u, fur_lut, _buffer_sizes);
    {
        float ky0_ = (1.0 - _e94.w) * _e100;
        float ky1_ = _e94.w * _e100;
        float w0_1 = ky0_ * (1.0 - _e98.w);
        float w1_1 = ky0_ * _e98.w;
        float w2_1 = ky1_ * (1.0 - _e98.w);
        float w3_ = ky1_ * _e98.w;
        uint i0_ = (_e94.i * _e12) + _e98.i;
        uint2 loop_bound_3 = uint2(4294967295u);
        bool loop_init_3 = true;
        while(true) {
            if (metal::all(loop_bound_3 == uint2(0u))) { break; }
            loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
            if (!loop_init_3) {
                uint _e168 = ch_2;
                ch_2 = _e168 + 1u;
            }
            loop_init_3 = false;
            uint _e126 = ch_2;
            if (_e126 < 2u) {
            } else {
                break;
            }
            {
                uint _e132 = ch_2;
                float _e134 = fur_half((s0_ + (2u * i0_)) + _e132, fur_lut, _buffer_sizes);
                uint _e140 = ch_2;
                float _e142 = fur_half((s0_ + (2u * (i0_ + 1u))) + _e140, fur_lut, _buffer_sizes);
                uint _e147 = ch_2;
                float _e149 = fur_half((s0_ + (2u * (i0_ + _e12))) + _e147, fur_lut, _buffer_sizes);
                uint _e156 = ch_2;
                float _e158 = fur_half((s0_ + (2u * ((i0_ + _e12) + 1u))) + _e156, fur_lut, _buffer_sizes);
                uint _e159 = ch_2;
                ms.inner[_e159] = (((w0_1 * _e134) + (w1_1 * _e142)) + (w2_1 * _e149)) + (w3_ * _e158);
            }
        }
    }
    float front_w = metal::min(abs_phi * 0.31830987, 1.0);
    FurAxis _e177 = fur_axis(false, 0.63661975, _e8);
    FurLoc _e179 = fur_locate(_e177, metal::abs(theta_r_2));
    FurAxis _e182 = fur_axis(false, 0.31830987, _e10);
    FurLoc _e183 = fur_locate(_e182, abs_phi);
    float _e185 = fur_unbias(1u, fur_lut, _buffer_sizes);
    float ny0_ = (1.0 - _e179.w) * _e185;
    float ny1_ = _e179.w * _e185;
    float v0_8 = ny0_ * (1.0 - _e183.w);
    float v1_8 = ny0_ * _e183.w;
    float v2_ = ny1_ * (1.0 - _e183.w);
    float v3_ = ny1_ * _e183.w;
    uint j0_ = (_e179.i * _e10) + _e183.i;
    FurColour _e208 = fur_locate_colour(sigma_ca_1, fur_lut, _buffer_sizes);
    uint _e209 = fur_n_plane_halves(fur_lut, _buffer_sizes);
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e342 = c;
            c = _e342 + 1u;
        }
        loop_init_4 = false;
        uint _e213 = c;
        if (_e213 < 3u) {
        } else {
            break;
        }
        {
            uint _e217 = c;
            uint _e220 = c;
            uint _e223 = c;
            metal::float3 tw = metal::float3(_e208.w0_[_e217], _e208.w1_[_e220], _e208.w2_[_e223]);
            type_11 l_8 = type_11 {{tw.x * v0_8, tw.x * v2_, tw.y * v0_8, tw.y * v2_, tw.z * v0_8, tw.z * v2_}};
            type_11 r_14 = type_11 {{tw.x * v1_8, tw.x * v3_, tw.y * v1_8, tw.y * v3_, tw.z * v1_8, tw.z * v3_}};
            uint _e254 = c;
            uint h_3 = n0_ + (4u * (_e208.plane[_e254] + j0_));
            type_12 rows = type_12 {{h_3, h_3 + (4u * _e10), h_3 + _e209, (h_3 + _e209) + (4u * _e10), h_3 + (2u * _e209), (h_3 + (2u * _e209)) + (4u * _e10)}};
            f = 0u;
            uint2 loop_bound_5 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_5 == uint2(0u))) { break; }
                loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e339 = f;
                    f = _e339 + 1u;
                }
                loop_init_5 = false;
                uint _e279 = f;
                if (_e279 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e283 = f;
                    float _e285 = fur_half(rows.inner[0] + _e283, fur_lut, _buffer_sizes);
                    left = _e285 * l_8.inner[0];
                    uint _e292 = f;
                    float _e294 = fur_half((rows.inner[0] + 4u) + _e292, fur_lut, _buffer_sizes);
                    right = _e294 * r_14.inner[0];
                    i = 1u;
                    uint2 loop_bound_6 = uint2(4294967295u);
                    bool loop_init_6 = true;
                    while(true) {
                        if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                        loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                        if (!loop_init_6) {
                            uint _e325 = i;
                            i = _e325 + 1u;
                        }
                        loop_init_6 = false;
                        uint _e300 = i;
                        if (_e300 < 6u) {
                        } else {
                            break;
                        }
                        {
                            float _e303 = left;
                            uint _e304 = i;
                            uint _e306 = f;
                            float _e308 = fur_half(rows.inner[_e304] + _e306, fur_lut, _buffer_sizes);
                            uint _e309 = i;
                            left = _e303 + (_e308 * l_8.inner[_e309]);
                            float _e313 = right;
                            uint _e314 = i;
                            uint _e318 = f;
                            float _e320 = fur_half((rows.inner[_e314] + 4u) + _e318, fur_lut, _buffer_sizes);
                            uint _e321 = i;
                            right = _e313 + (_e320 * r_14.inner[_e321]);
                        }
                    }
                    uint _e329 = f;
                    uint _e331 = c;
                    float _e334 = left;
                    float _e335 = right;
                    n.inner[(3u * _e329) + _e331] = metal::max(_e334 + _e335, 0.0);
                }
            }
        }
    }
    uint2 loop_bound_7 = uint2(4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (metal::all(loop_bound_7 == uint2(0u))) { break; }
        loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e390 = f_1;
            f_1 = _e390 + 1u;
        }
        loop_init_7 = false;
        uint _e348 = f_1;
        if (_e348 < 4u) {
        } else {
            break;
        }
        {
            uint _e354 = f_1;
            float _e356 = fur_half((n0_ + (4u * j0_)) + _e354, fur_lut, _buffer_sizes);
            uint _e362 = f_1;
            float _e364 = fur_half((n0_ + (4u * (j0_ + 1u))) + _e362, fur_lut, _buffer_sizes);
            uint _e369 = f_1;
            float _e371 = fur_half((n0_ + (4u * (j0_ + _e10))) + _e369, fur_lut, _buffer_sizes);
            uint _e378 = f_1;
            float _e380 = fur_half((n0_ + (4u * ((j0_ + _e10) + 1u))) + _e378, fur_lut, _buffer_sizes);
            uint _e381 = f_1;
            nl.inner[_e381] = (((v0_8 * _e356) + (v1_8 * _e364)) + (v2_ * _e371)) + (v3_ * _e380);
        }
    }
    type_7 _e393 = m;
    type_8 _e394 = ms;
    type_9 _e395 = n;
    type_10 _e396 = nl;
    return FurLookups {_e393, _e394, _e395, _e396, front_w, inv_cos2_};
}

FurFamilies fur_assemble(
    FurLookups l
) {
    type_13 f_2 = {};
    uint k_1 = 0u;
    float mss = l.ms.inner[0] + (l.front * (l.ms.inner[1] - l.ms.inner[0]));
    type_10 lon = type_10 {{l.m.inner[0], l.m.inner[1], l.m.inner[2], mss}};
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_8 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_8) {
            uint _e51 = k_1;
            k_1 = _e51 + 1u;
        }
        loop_init_8 = false;
        uint _e21 = k_1;
        if (_e21 < 4u) {
        } else {
            break;
        }
        {
            uint _e24 = k_1;
            float weight = lon.inner[_e24] * l.inv_cos2_;
            uint _e28 = k_1;
            uint _e32 = k_1;
            uint _e37 = k_1;
            uint _e44 = k_1;
            f_2.inner[_e28] = metal::float3(l.n.inner[3u * _e32], l.n.inner[(3u * _e37) + 1u], l.n.inner[(3u * _e44) + 2u]) * weight;
        }
    }
    metal::float3 _e55 = f_2.inner[0];
    metal::float3 _e57 = f_2.inner[1];
    metal::float3 _e59 = f_2.inner[2];
    metal::float3 _e61 = f_2.inner[3];
    metal::float3 _e63 = f_2.inner[0];
    metal::float3 _e65 = f_2.inner[1];
    metal::float3 _e68 = f_2.inner[2];
    metal::float3 _e71 = f_2.inner[3];
    return FurFamilies {_e55, _e57, _e59, _e61, ((_e63 + _e65) + _e68) + _e71};
}

FurFamilies fur_eval_far(
    float theta_i_2,
    float theta_r_3,
    float phi_1,
    metal::float3 sigma_ca_2,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool _e4 = fur_valid(theta_i_2, theta_r_3, phi_1);
    if (!(_e4)) {
        FurFamilies _e6 = fur_zero();
        return _e6;
    }
    FurLookups _e7 = fur_lookups(theta_i_2, theta_r_3, phi_1, sigma_ca_2, fur_lut, _buffer_sizes);
    FurFamilies _e8 = fur_assemble(_e7);
    return _e8;
}

float fur_asin(
    float x_5
) {
    float ax_3 = metal::min(metal::abs(x_5), 1.0);
    float x2_ = ax_3 * ax_3;
    float x4_ = x2_ * x2_;
    float p01_1 = (-0.001262491 * ax_3) + 0.00667009;
    float p23_1 = (-0.017088126 * ax_3) + 0.03089188;
    float p45_1 = (-0.050174303 * ax_3) + 0.08897899;
    float p67_1 = (-0.2145988 * ax_3) + FUR_HALF_PI;
    float poly = (((p01_1 * x2_) + p23_1) * x4_) + ((p45_1 * x2_) + p67_1);
    float r_15 = FUR_HALF_PI - (metal::sqrt(1.0 - ax_3) * poly);
    return ((as_type<uint>(x_5) & 2147483648u) != 0u) ? -(metal::abs(r_15)) : metal::abs(r_15);
}

float fur_atan_poly(
    float t_1
) {
    float t2_ = t_1 * t_1;
    float t4_ = t2_ * t2_;
    float p01_2 = (0.0029202348 * t_1) + -0.016366187;
    float p23_2 = (0.043209206 * t_1) + -0.07552008;
    float p45_2 = (0.10665919 * t_1) + -0.14211038;
    float p67_2 = (0.19993772 * t_1) + -0.33333153;
    return (((p01_2 * t2_) + p23_2) * t4_) + ((p45_2 * t2_) + p67_2);
}

float fur_atan2_(
    float y_1,
    float x_6
) {
    float r = {};
    float ax_4 = metal::abs(x_6);
    float ay = metal::abs(y_1);
    float a_8 = metal::min(ax_4, ay) / metal::max(metal::max(ax_4, ay), 0.000000000000000000000000000000000000011754944);
    float t_12 = a_8 * a_8;
    float _e10 = fur_atan_poly(t_12);
    r = a_8 + (a_8 * (t_12 * _e10));
    float _e15 = r;
    float _e17 = r;
    r = (ay > ax_4) ? (FUR_HALF_PI - _e17) : _e15;
    float _e21 = r;
    float _e23 = r;
    r = (x_6 < 0.0) ? (FUR_PI - _e23) : _e21;
    float _e28 = r;
    float _e29 = r;
    return ((as_type<uint>(y_1) & 2147483648u) != 0u) ? -(_e29) : _e28;
}

FurDirAngles fur_angles_from_dirs(
    metal::float3 wi,
    metal::float3 wr,
    metal::float3 u
) {
    bool local_8 = {};
    bool local_9 = {};
    bool local_10 = {};
    bool local_11 = {};
    FurDirAngles none = FurDirAngles {0.0, 0.0, 0.0, false};
    float ii = metal::dot(wi, wi);
    float rr = metal::dot(wr, wr);
    float uu = metal::dot(u, u);
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
    float ni = metal::sqrt(ii);
    float nr = metal::sqrt(rr);
    float nu = metal::sqrt(uu);
    if (!((ni < 0.000000000000000000000000000000000000011754944))) {
        local_10 = nr < 0.000000000000000000000000000000000000011754944;
    } else {
        local_10 = true;
    }
    bool _e33 = local_10;
    if (!(_e33)) {
        local_11 = nu < 0.000000000000000000000000000000000000011754944;
    } else {
        local_11 = true;
    }
    bool _e39 = local_11;
    if (_e39) {
        return none;
    }
    metal::float3 un = u * (1.0 / nu);
    float a_9 = metal::dot(wi, un);
    float b_3 = metal::dot(wr, un);
    float _e51 = fur_asin(metal::clamp(a_9 * (1.0 / ni), -1.0, 1.0));
    float _e58 = fur_asin(metal::clamp(b_3 * (1.0 / nr), -1.0, 1.0));
    float y_6 = metal::dot(un, metal::cross(wi, wr));
    float x_18 = metal::dot(wi, wr) - (a_9 * b_3);
    float _e64 = fur_atan2_(y_6, x_18);
    return FurDirAngles {_e51, _e58, metal::abs(_e64), true};
}

FurFamilies fur_eval_far_dirs(
    metal::float3 wi_1,
    metal::float3 wr_1,
    metal::float3 u_1,
    metal::float3 sigma_ca_3,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurDirAngles _e4 = fur_angles_from_dirs(wi_1, wr_1, u_1);
    if (!(_e4.ok)) {
        FurFamilies _e7 = fur_zero();
        return _e7;
    }
    FurFamilies _e11 = fur_eval_far(_e4.theta_i, _e4.theta_r, _e4.phi, sigma_ca_3, fur_lut, _buffer_sizes);
    return _e11;
}

float fur_node(
    FurDensity d_1,
    uint row,
    uint j,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e6 = fur_word(4u, fur_lut, _buffer_sizes);
    uint n0_1 = FUR_HEADER_HALVES + (3u * _e6);
    uint _e9 = fur_n_plane_halves(fur_lut, _buffer_sizes);
    uint _e11 = fur_word(FUR_N_ABS_WORD, fur_lut, _buffer_sizes);
    uint s0_1 = n0_1 + (_e9 * _e11);
    type_14 starts = type_14 {{FUR_HEADER_HALVES, n0_1, s0_1}};
    type_14 chans = type_14 {{3u, 4u, 2u}};
    uint base = (starts.inner[d_1.table] + (((row * d_1.nodes) + j) * chans.inner[d_1.table])) + d_1.channel;
    float _e30 = fur_half(base, fur_lut, _buffer_sizes);
    float _e32 = fur_unbias(d_1.table, fur_lut, _buffer_sizes);
    return _e30 * _e32;
}

FurRows fur_rows(
    FurDensity d_2,
    uint row_1,
    float w,
    float origin
) {
    return FurRows {d_2, metal::min(row_1, d_2.rows - 1u), metal::min(row_1 + 1u, d_2.rows - 1u), w, origin, 0u};
}

FurRows fur_rows_weighted(
    uint weighting,
    uint row_2,
    float w_1,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurDensity _e8 = fur_density((weighting == 2u) ? 9u : 6u, fur_lut, _buffer_sizes);
    return FurRows {_e8, metal::min(row_2, _e8.rows - 1u), metal::min(row_2 + 1u, _e8.rows - 1u), w_1, 0.0, weighting};
}

float fur_rows_value(
    FurRows r_1,
    uint j_1,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = fur_node(r_1.d, r_1.r0_, j_1, fur_lut, _buffer_sizes);
    if (r_1.w == 0.0) {
        return _e4;
    }
    float _e10 = fur_node(r_1.d, r_1.r1_, j_1, fur_lut, _buffer_sizes);
    return ((1.0 - r_1.w) * _e4) + (r_1.w * _e10);
}

float fur_blended_prefix(
    FurRows r_2,
    FurDensity d_3,
    uint k_2,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e11 = fur_f32_at(d_3.prefix_at + (4u * ((r_2.r0_ * d_3.entries) + k_2)), fur_lut, _buffer_sizes);
    if (r_2.w == 0.0) {
        return _e11;
    }
    float _e23 = fur_f32_at(d_3.prefix_at + (4u * ((r_2.r1_ * d_3.entries) + k_2)), fur_lut, _buffer_sizes);
    return ((1.0 - r_2.w) * _e11) + (r_2.w * _e23);
}

float fur_rows_prefix(
    FurRows r_3,
    uint k_3,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e3 = fur_blended_prefix(r_3, r_3.d, k_3, fur_lut, _buffer_sizes);
    if (r_3.weighting == 1u) {
        FurDensity _e8 = fur_density(9u, fur_lut, _buffer_sizes);
        float _e9 = fur_blended_prefix(r_3, _e8, k_3, fur_lut, _buffer_sizes);
        return _e3 - _e9;
    }
    return _e3;
}

float fur_rows_total(
    FurRows r_4,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e5 = fur_rows_prefix(r_4, r_4.d.entries - 1u, fur_lut, _buffer_sizes);
    return _e5;
}

float fur_linear_mass(
    float v0_,
    float v1_,
    float len
) {
    return (0.5 * len) * (v0_ + v1_);
}

float fur_invert_linear(
    float v0_1,
    float v1_1,
    float len_1,
    float t_2
) {
    float s = 0.0;
    bool local_12 = {};
    bool local_13 = {};
    if (!((len_1 > 0.0))) {
        return 0.0;
    }
    if (t_2 > 0.0) {
        float disc = metal::max((v0_1 * v0_1) + (((2.0 * (v1_1 - v0_1)) * t_2) / len_1), 0.0);
        float den = v0_1 + metal::sqrt(disc);
        if (den > 0.0) {
            s = metal::clamp((2.0 * t_2) / den, 0.0, len_1);
        } else {
            s = len_1;
        }
    }
    float inset = len_1 * 0.0000009536743;
    if (v0_1 <= 0.0) {
        float _e36 = s;
        local_12 = _e36 < inset;
    } else {
        local_12 = false;
    }
    bool _e39 = local_12;
    if (_e39) {
        return inset;
    }
    if (v1_1 <= 0.0) {
        float _e44 = s;
        local_13 = _e44 > (len_1 - inset);
    } else {
        local_13 = false;
    }
    bool _e48 = local_13;
    if (_e48) {
        return len_1 - inset;
    }
    float _e50 = s;
    return _e50;
}

float fur_weighted_linear_mass(
    float v0_2,
    float v1_2,
    float a_1,
    float b,
    float len_2
) {
    return (len_2 * (((a_1 * v0_2) + (0.5 * ((a_1 * v1_2) + (b * v0_2)))) + (b * v1_2))) * 0.33333334;
}

float fur_invert_weighted_linear(
    float v0_3,
    float v1_3,
    float a_2,
    float b_1,
    float len_3,
    float t_3
) {
    float x_7 = 0.5;
    bool local_14 = {};
    float lo = 0.0;
    float hi = 1.0;
    uint k_4 = 0u;
    float next = {};
    bool local_15 = {};
    bool local_16 = {};
    bool local_17 = {};
    if (!((len_3 > 0.0))) {
        return 0.0;
    }
    float q0_ = a_2 * v0_3;
    float cb = (a_2 * (v1_3 - v0_3)) + (v0_3 * (b_1 - a_2));
    float cc = (b_1 - a_2) * (v1_3 - v0_3);
    float q1_ = b_1 * v1_3;
    float goal = t_3 / len_3;
    float total_1 = (q0_ + (0.5 * cb)) + (0.33333334 * cc);
    float lin = 0.5 * (q0_ + q1_);
    if (total_1 > 0.0) {
        local_14 = lin > 0.0;
    } else {
        local_14 = false;
    }
    bool _e39 = local_14;
    if (_e39) {
        float _e43 = fur_invert_linear(q0_, q1_, 1.0, goal * (lin / total_1));
        x_7 = _e43;
    }
    uint2 loop_bound_9 = uint2(4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (metal::all(loop_bound_9 == uint2(0u))) { break; }
        loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e102 = k_4;
            k_4 = _e102 + 1u;
        }
        loop_init_9 = false;
        uint _e50 = k_4;
        if (_e50 < 8u) {
        } else {
            break;
        }
        {
            float _e53 = x_7;
            float _e54 = x_7;
            float _e57 = x_7;
            float fx = (_e53 * (q0_ + (_e54 * ((0.5 * cb) + ((_e57 * 0.33333334) * cc))))) - goal;
            if (fx > 0.0) {
                float _e68 = x_7;
                hi = _e68;
            } else {
                float _e69 = x_7;
                lo = _e69;
            }
            float _e70 = x_7;
            float _e71 = x_7;
            float d_7 = q0_ + (_e70 * (cb + (_e71 * cc)));
            float _e76 = lo;
            float _e77 = hi;
            next = 0.5 * (_e76 + _e77);
            if (d_7 > 0.0) {
                float _e84 = x_7;
                float n_2 = _e84 - (fx / d_7);
                float _e87 = lo;
                if (n_2 >= _e87) {
                    float _e91 = hi;
                    local_15 = n_2 <= _e91;
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
            bool done = metal::abs(_e95 - _e96) <= 0.00000012;
            float _e101 = next;
            x_7 = _e101;
            if (done) {
                break;
            }
        }
    }
    float _e105 = x_7;
    float s_2 = metal::clamp(_e105 * len_3, 0.0, len_3);
    float inset_1 = len_3 * 0.0000009536743;
    if (q0_ <= 0.0) {
        local_16 = s_2 < inset_1;
    } else {
        local_16 = false;
    }
    bool _e117 = local_16;
    if (_e117) {
        return inset_1;
    }
    if (q1_ <= 0.0) {
        local_17 = s_2 > (len_3 - inset_1);
    } else {
        local_17 = false;
    }
    bool _e125 = local_17;
    if (_e125) {
        return len_3 - inset_1;
    }
    return s_2;
}

metal::float2 fur_rows_weights(
    FurRows r_5,
    uint j_2
) {
    float inv = 1.0 / static_cast<float>(r_5.d.nodes - 1u);
    metal::float2 ab = metal::float2(static_cast<float>(j_2) * inv, static_cast<float>(j_2 + 1u) * inv);
    if (r_5.weighting == 1u) {
        return metal::float2(1.0 - ab.x, 1.0 - ab.y);
    }
    return ab;
}

float fur_rows_segment_mass(
    FurRows r_6,
    uint j_3,
    float v0_4,
    float v1_4
) {
    if (r_6.weighting == 0u) {
        float _e9 = fur_linear_mass(v0_4, v1_4, r_6.d.step);
        return _e9;
    }
    metal::float2 _e10 = fur_rows_weights(r_6, j_3);
    float _e15 = fur_weighted_linear_mass(v0_4, v1_4, _e10.x, _e10.y, r_6.d.step);
    return _e15;
}

float fur_rows_invert_segment(
    FurRows r_7,
    uint j_4,
    float v0_5,
    float v1_5,
    float t_4
) {
    if (r_7.weighting == 0u) {
        float _e10 = fur_invert_linear(v0_5, v1_5, r_7.d.step, t_4);
        return _e10;
    }
    metal::float2 _e11 = fur_rows_weights(r_7, j_4);
    float _e16 = fur_invert_weighted_linear(v0_5, v1_5, _e11.x, _e11.y, r_7.d.step, t_4);
    return _e16;
}

float fur_unit(
    float u_2
) {
    if (u_2 > 0.0) {
        return metal::min(u_2, 0.99999994);
    }
    return 0.0;
}

float fur_rows_invert(
    FurRows r_8,
    float t_5,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint lo_1 = 0u;
    uint len_4 = {};
    float acc_2 = {};
    float prev = {};
    bool have_last = false;
    uint last_j = 0u;
    float last_v0_ = 0.0;
    float last_v1_ = 0.0;
    float last_m = 0.0;
    uint j_5 = {};
    len_4 = r_8.d.entries - 1u;
    uint2 loop_bound_10 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        uint _e9 = len_4;
        if (_e9 <= 1u) {
            break;
        }
        uint _e12 = len_4;
        uint half_1 = naga_div(_e12, 2u);
        uint _e15 = lo_1;
        uint _e16 = lo_1;
        uint _e18 = lo_1;
        float _e20 = fur_rows_prefix(r_8, _e18 + half_1, fur_lut, _buffer_sizes);
        lo_1 = (_e20 < t_5) ? (_e16 + half_1) : _e15;
        uint _e23 = len_4;
        len_4 = _e23 - half_1;
    }
    uint _e25 = lo_1;
    uint first = _e25 * r_8.d.block;
    uint end = metal::min(first + r_8.d.block, r_8.d.nodes - 1u);
    uint _e37 = lo_1;
    float _e38 = fur_rows_prefix(r_8, _e37, fur_lut, _buffer_sizes);
    acc_2 = _e38;
    float _e40 = fur_rows_value(r_8, first, fur_lut, _buffer_sizes);
    prev = _e40;
    j_5 = first;
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_10 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_10) {
            uint _e85 = j_5;
            j_5 = _e85 + 1u;
        }
        loop_init_10 = false;
        uint _e53 = j_5;
        if (_e53 < end) {
        } else {
            break;
        }
        {
            uint _e55 = j_5;
            float _e58 = fur_rows_value(r_8, _e55 + 1u, fur_lut, _buffer_sizes);
            uint _e59 = j_5;
            float _e60 = prev;
            float _e61 = fur_rows_segment_mass(r_8, _e59, _e60, _e58);
            if (_e61 > 0.0) {
                float _e64 = acc_2;
                if ((t_5 - _e64) <= _e61) {
                    uint _e67 = j_5;
                    float _e68 = prev;
                    float _e69 = acc_2;
                    float _e71 = fur_rows_invert_segment(r_8, _e67, _e68, _e58, t_5 - _e69);
                    uint _e73 = j_5;
                    return (r_8.origin + (static_cast<float>(_e73) * r_8.d.step)) + _e71;
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
            acc_2 = _e83 + _e61;
            prev = _e58;
        }
    }
    bool _e88 = have_last;
    if (_e88) {
        float _e89 = last_m;
        float _e92 = last_v0_;
        float _e93 = last_v1_;
        float whole = (r_8.weighting == 0u) ? (r_8.d.step * (_e92 + _e93)) : _e89;
        uint _e100 = last_j;
        float _e101 = last_v0_;
        float _e102 = last_v1_;
        float _e103 = fur_rows_invert_segment(r_8, _e100, _e101, _e102, whole);
        uint _e105 = last_j;
        return (r_8.origin + (static_cast<float>(_e105) * r_8.d.step)) + _e103;
    }
    return r_8.origin + (static_cast<float>(end) * r_8.d.step);
}

float fur_rows_invert_between(
    FurRows r_9,
    float t0_,
    float t1_,
    float u_3,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float inset_2 = (t1_ - t0_) * 0.0000009536743;
    float _e7 = fur_unit(u_3);
    float t_13 = metal::clamp(t0_ + (_e7 * (t1_ - t0_)), t0_ + inset_2, t1_ - inset_2);
    float _e14 = fur_rows_invert(r_9, t_13, fur_lut, _buffer_sizes);
    return _e14;
}

float fur_pole_keep(
    float cos_theta_i
) {
    float c_3 = metal::max(cos_theta_i, 0.000001);
    return metal::min((c_3 * c_3) * 10000.0, 1.0);
}

float fur_sliver_keep(
    float s_in
) {
    float s_3 = metal::abs(s_in);
    if (!((s_3 < FUR_POLE_SLIVER))) {
        return 1.0;
    }
    float s2_ = s_3 * s_3;
    return metal::min((s2_ * (1.0 - (s2_ * 0.33333334))) * 10000.0, 1.0);
}

float fur_sliver_piece_mass(
    float v0_6,
    float v1_6,
    float len0_,
    float x0_,
    float pole,
    float len_5
) {
    bool local_18 = {};
    float acc_3 = 0.0;
    uint k_5 = 0u;
    if (len_5 > 0.0) {
        local_18 = len0_ > 0.0;
    } else {
        local_18 = false;
    }
    bool _e13 = local_18;
    if (!(_e13)) {
        return 0.0;
    }
    float slope = (v1_6 - v0_6) / len0_;
    type_7 t_14 = type_7 {{0.11270166, 0.5, 0.8872983}};
    type_7 w_5 = type_7 {{0.2777778, 0.44444445, 0.2777778}};
    uint2 loop_bound_12 = uint2(4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e47 = k_5;
            k_5 = _e47 + 1u;
        }
        loop_init_11 = false;
        uint _e30 = k_5;
        if (_e30 < 3u) {
        } else {
            break;
        }
        {
            uint _e33 = k_5;
            float d_8 = t_14.inner[_e33] * len_5;
            float _e36 = acc_3;
            uint _e37 = k_5;
            float _e44 = fur_sliver_keep((x0_ - pole) + d_8);
            acc_3 = _e36 + ((w_5.inner[_e37] * (v0_6 + (slope * d_8))) * _e44);
        }
    }
    float _e50 = acc_3;
    return _e50 * len_5;
}

float fur_invert_sliver_piece(
    float v0_7,
    float v1_7,
    float len_6,
    float x0_1,
    float pole_1,
    float t_6
) {
    bool local_19 = {};
    float lo_2 = 0.0;
    float hi_1 = {};
    float d_4 = {};
    uint k_6 = 0u;
    float next_1 = {};
    bool local_20 = {};
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
    float slope_1 = (v1_7 - v0_7) / len_6;
    hi_1 = len_6;
    d_4 = len_6 * (t_6 / _e6);
    uint2 loop_bound_13 = uint2(4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (metal::all(loop_bound_13 == uint2(0u))) { break; }
        loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e76 = k_6;
            k_6 = _e76 + 1u;
        }
        loop_init_12 = false;
        uint _e31 = k_6;
        if (_e31 < 16u) {
        } else {
            break;
        }
        {
            float _e34 = d_4;
            float _e35 = fur_sliver_piece_mass(v0_7, v1_7, len_6, x0_1, pole_1, _e34);
            float f_8 = _e35 - t_6;
            if (f_8 > 0.0) {
                float _e39 = d_4;
                hi_1 = _e39;
            } else {
                float _e40 = d_4;
                lo_2 = _e40;
            }
            float _e41 = d_4;
            float _e45 = d_4;
            float _e47 = fur_sliver_keep((x0_1 - pole_1) + _e45);
            float dens = (v0_7 + (slope_1 * _e41)) * _e47;
            float _e49 = lo_2;
            float _e50 = hi_1;
            next_1 = 0.5 * (_e49 + _e50);
            if (dens > 0.0) {
                float _e57 = d_4;
                float n_3 = _e57 - (f_8 / dens);
                float _e60 = lo_2;
                if (n_3 >= _e60) {
                    float _e64 = hi_1;
                    local_20 = n_3 <= _e64;
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
            bool done_1 = metal::abs(_e68 - _e69) <= (0.00000012 * len_6);
            float _e75 = next_1;
            d_4 = _e75;
            if (done_1) {
                break;
            }
        }
    }
    float _e79 = d_4;
    return metal::clamp(_e79, 0.0, len_6);
}

metal::float3 fur_rows_sliver(
    FurRows r_10,
    FurAxis ax,
    float a_3,
    float b_2,
    float pole_2,
    float t_7,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float off = 0.0;
    metal::float3 out_1 = {};
    uint j_6 = {};
    bool local_21 = {};
    bool local_22 = {};
    FurLoc _e6 = fur_locate(ax, a_3);
    FurLoc _e7 = fur_locate(ax, b_2);
    float at_2 = a_3 - pole_2;
    out_1 = metal::float3(0.0, 0.0, b_2);
    j_6 = _e6.i;
    uint2 loop_bound_14 = uint2(4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e92 = j_6;
            j_6 = _e92 + 1u;
        }
        loop_init_13 = false;
        uint _e17 = j_6;
        if (_e17 <= _e7.i) {
        } else {
            break;
        }
        {
            uint _e21 = j_6;
            float w0_2 = (_e21 == _e6.i) ? _e6.w : 0.0;
            uint _e27 = j_6;
            float w1_2 = (_e27 == _e7.i) ? _e7.w : 1.0;
            if (w1_2 > w0_2) {
                uint _e33 = j_6;
                float _e34 = fur_rows_value(r_10, _e33, fur_lut, _buffer_sizes);
                uint _e35 = j_6;
                float _e38 = fur_rows_value(r_10, _e35 + 1u, fur_lut, _buffer_sizes);
                float len_7 = (w1_2 - w0_2) * r_10.d.step;
                float v0_9 = _e34 + ((_e38 - _e34) * w0_2);
                float v1_9 = _e34 + ((_e38 - _e34) * w1_2);
                float _e49 = off;
                float _e52 = fur_sliver_piece_mass(v0_9, v1_9, len_7, at_2 + _e49, 0.0, len_7);
                if (t_7 >= 0.0) {
                    local_21 = _e52 > 0.0;
                } else {
                    local_21 = false;
                }
                bool _e60 = local_21;
                if (_e60) {
                    float _e64 = out_1.y;
                    local_22 = (t_7 - _e64) <= _e52;
                } else {
                    local_22 = false;
                }
                bool _e68 = local_22;
                if (_e68) {
                    float _e70 = off;
                    float _e71 = off;
                    float _e75 = out_1.y;
                    float _e77 = fur_invert_sliver_piece(v0_9, v1_9, len_7, at_2 + _e71, 0.0, t_7 - _e75);
                    out_1.z = a_3 + (_e70 + _e77);
                    metal::float3 _e80 = out_1;
                    return _e80;
                }
                float _e83 = out_1.x;
                float _e84 = fur_linear_mass(v0_9, v1_9, len_7);
                out_1.x = _e83 + _e84;
                float _e88 = out_1.y;
                out_1.y = _e88 + _e52;
                float _e90 = off;
                off = _e90 + len_7;
            }
        }
    }
    metal::float3 _e95 = out_1;
    return _e95;
}

FurRange fur_rows_range(
    FurRows r_11,
    FurAxis ax_1,
    float lo_3,
    float hi_2,
    float start,
    float raw,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 _e9 = fur_rows_sliver(r_11, ax_1, lo_3, lo_3 + FUR_POLE_SLIVER, lo_3, -1.0, fur_lut, _buffer_sizes);
    metal::float3 _e13 = fur_rows_sliver(r_11, ax_1, hi_2 - FUR_POLE_SLIVER, hi_2, hi_2, -1.0, fur_lut, _buffer_sizes);
    return FurRange {lo_3, hi_2, start, raw, metal::float4(_e9.x, _e9.y, _e13.x, _e13.y)};
}

float fur_range_kept(
    FurRange g_1
) {
    return (metal::max((g_1.raw - g_1.s.x) - g_1.s.z, 0.0) + g_1.s.y) + g_1.s.w;
}

float fur_rows_invert_kept(
    FurRows r_12,
    FurAxis ax_2,
    FurRange g_2,
    float u_4,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool local_23 = {};
    float _e4 = fur_range_kept(g_2);
    float inset_3 = _e4 * 0.0000009536743;
    float _e7 = fur_unit(u_4);
    float t0_1 = metal::clamp(_e7 * _e4, inset_3, _e4 - inset_3);
    if (t0_1 < g_2.s.y) {
        metal::float3 _e19 = fur_rows_sliver(r_12, ax_2, g_2.lo, g_2.lo + FUR_POLE_SLIVER, g_2.lo, t0_1, fur_lut, _buffer_sizes);
        return _e19.z;
    }
    float mid = metal::max((g_2.raw - g_2.s.x) - g_2.s.z, 0.0);
    float t_15 = t0_1 - g_2.s.y;
    if (!((t_15 <= mid))) {
        local_23 = !((g_2.s.w > 0.0));
    } else {
        local_23 = true;
    }
    bool _e43 = local_23;
    if (_e43) {
        float _e50 = fur_rows_invert(r_12, (g_2.start + g_2.s.x) + metal::min(t_15, mid), fur_lut, _buffer_sizes);
        return _e50;
    }
    metal::float3 _e57 = fur_rows_sliver(r_12, ax_2, g_2.hi - FUR_POLE_SLIVER, g_2.hi, g_2.hi, t_15 - mid, fur_lut, _buffer_sizes);
    return _e57.z;
}

FurAxis fur_sum_axis(
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = fur_word(4u, fur_lut, _buffer_sizes);
    FurAxis _e4 = fur_axis(true, 0.15915494, _e3);
    return _e4;
}

FurMAt fur_m_at(
    FurLoc l_1,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurMAt out_2 = FurMAt {metal::float3(0.0), metal::float3(0.0)};
    uint g_3 = 0u;
    FurDensity _e2 = fur_density(0u, fur_lut, _buffer_sizes);
    float off_1 = l_1.w * _e2.step;
    uint2 loop_bound_15 = uint2(4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (metal::all(loop_bound_15 == uint2(0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e45 = g_3;
            g_3 = _e45 + 1u;
        }
        loop_init_14 = false;
        uint _e14 = g_3;
        if (_e14 < 3u) {
        } else {
            break;
        }
        {
            uint _e17 = g_3;
            FurDensity _e18 = fur_density(_e17, fur_lut, _buffer_sizes);
            float _e21 = fur_node(_e18, 0u, l_1.i, fur_lut, _buffer_sizes);
            float _e26 = fur_node(_e18, 0u, l_1.i + 1u, fur_lut, _buffer_sizes);
            float at_3 = _e21 + ((_e26 - _e21) * l_1.w);
            uint _e32 = g_3;
            float _e39 = fur_f32_at(_e18.prefix_at + (4u * l_1.i), fur_lut, _buffer_sizes);
            float _e40 = fur_linear_mass(_e21, at_3, off_1);
            out_2.cdf[_e32] = _e39 + _e40;
            uint _e43 = g_3;
            out_2.value[_e43] = at_3;
        }
    }
    FurMAt _e48 = out_2;
    return _e48;
}

metal::float3 fur_m_cdf(
    float x_8,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurAxis _e1 = fur_sum_axis(fur_lut, _buffer_sizes);
    FurLoc _e2 = fur_locate(_e1, x_8);
    FurMAt _e3 = fur_m_at(_e2, fur_lut, _buffer_sizes);
    return _e3.cdf;
}

float fur_row_total(
    FurDensity d_5,
    FurLoc l_2,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e17 = fur_f32_at(d_5.prefix_at + (4u * (((metal::min(l_2.i, d_5.rows - 1u) * d_5.entries) + d_5.entries) - 1u)), fur_lut, _buffer_sizes);
    float _e35 = fur_f32_at(d_5.prefix_at + (4u * (((metal::min(l_2.i + 1u, d_5.rows - 1u) * d_5.entries) + d_5.entries) - 1u)), fur_lut, _buffer_sizes);
    return _e17 + ((_e35 - _e17) * l_2.w);
}

float fur_positive(
    float v
) {
    bool local_24 = {};
    bool _e1 = fur_finite(v);
    if (_e1) {
        local_24 = v > 0.0;
    } else {
        local_24 = false;
    }
    bool _e7 = local_24;
    return _e7 ? v : 0.0;
}

FurAxis fur_ms_i_axis(
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = fur_word(7u, fur_lut, _buffer_sizes);
    FurAxis _e4 = fur_axis(true, 0.31830987, _e3);
    return _e4;
}

FurRows fur_ms_rows(
    uint half_,
    float theta_r_4,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = fur_word(8u, fur_lut, _buffer_sizes);
    FurAxis _e6 = fur_axis(true, 0.31830987, _e5);
    FurLoc _e7 = fur_locate(_e6, theta_r_4);
    FurDensity _e10 = fur_density(7u + half_, fur_lut, _buffer_sizes);
    FurRows _e14 = fur_rows(_e10, _e7.i, _e7.w, -1.5707964);
    return _e14;
}

FurParts fur_parts(
    float theta_r_5,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_18 ranges = {};
    uint g_4 = 0u;
    uint x_9 = 0u;
    float lo_x = theta_r_5 - FUR_HALF_PI;
    float hi_x = theta_r_5 + FUR_HALF_PI;
    metal::float3 _e5 = fur_m_cdf(lo_x, fur_lut, _buffer_sizes);
    metal::float3 _e6 = fur_m_cdf(hi_x, fur_lut, _buffer_sizes);
    metal::float3 mass = metal::max(_e6 - _e5, metal::float3(0.0));
    uint _e14 = fur_word(5u, fur_lut, _buffer_sizes);
    FurAxis _e15 = fur_axis(false, 0.63661975, _e14);
    FurLoc _e17 = fur_locate(_e15, metal::abs(theta_r_5));
    FurDensity _e19 = fur_density(6u, fur_lut, _buffer_sizes);
    float _e20 = fur_row_total(_e19, _e17, fur_lut, _buffer_sizes);
    FurDensity _e22 = fur_density(9u, fur_lut, _buffer_sizes);
    float _e23 = fur_row_total(_e22, _e17, fur_lut, _buffer_sizes);
    uint2 loop_bound_16 = uint2(4294967295u);
    bool loop_init_15 = true;
    while(true) {
        if (metal::all(loop_bound_16 == uint2(0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_15) {
            uint _e44 = g_4;
            g_4 = _e44 + 1u;
        }
        loop_init_15 = false;
        uint _e27 = g_4;
        if (_e27 < 3u) {
        } else {
            break;
        }
        {
            uint _e30 = g_4;
            FurDensity _e31 = fur_density(_e30, fur_lut, _buffer_sizes);
            FurRows _e35 = fur_rows(_e31, 0u, 0.0, -3.1415927);
            uint _e36 = g_4;
            FurAxis _e38 = fur_sum_axis(fur_lut, _buffer_sizes);
            uint _e39 = g_4;
            uint _e41 = g_4;
            FurRange _e43 = fur_rows_range(_e35, _e38, lo_x, hi_x, _e5[_e39], mass[_e41], fur_lut, _buffer_sizes);
            ranges.inner[_e36] = _e43;
        }
    }
    uint2 loop_bound_17 = uint2(4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (metal::all(loop_bound_17 == uint2(0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e64 = x_9;
            x_9 = _e64 + 1u;
        }
        loop_init_16 = false;
        uint _e49 = x_9;
        if (_e49 < 2u) {
        } else {
            break;
        }
        {
            uint _e52 = x_9;
            FurRows _e53 = fur_ms_rows(_e52, theta_r_5, fur_lut, _buffer_sizes);
            uint _e55 = x_9;
            FurAxis _e58 = fur_ms_i_axis(fur_lut, _buffer_sizes);
            float _e62 = fur_rows_total(_e53, fur_lut, _buffer_sizes);
            FurRange _e63 = fur_rows_range(_e53, _e58, -1.5707964, FUR_HALF_PI, 0.0, _e62, fur_lut, _buffer_sizes);
            ranges.inner[3u + _e55] = _e63;
        }
    }
    FurRange _e68 = ranges.inner[0];
    float _e69 = fur_range_kept(_e68);
    FurRange _e71 = ranges.inner[1];
    float _e72 = fur_range_kept(_e71);
    FurRange _e74 = ranges.inner[2];
    float _e75 = fur_range_kept(_e74);
    metal::float3 _e77 = fur_sphere_norms(theta_r_5, fur_lut, _buffer_sizes);
    metal::float3 kept = metal::float3(_e69, _e72, _e75) * _e77;
    FurDensity _e83 = fur_density(3u, fur_lut, _buffer_sizes);
    float _e84 = fur_row_total(_e83, _e17, fur_lut, _buffer_sizes);
    float _e86 = fur_positive((2.0 * kept.x) * _e84);
    FurDensity _e91 = fur_density(4u, fur_lut, _buffer_sizes);
    float _e92 = fur_row_total(_e91, _e17, fur_lut, _buffer_sizes);
    float _e94 = fur_positive((2.0 * kept.y) * _e92);
    FurDensity _e99 = fur_density(5u, fur_lut, _buffer_sizes);
    float _e100 = fur_row_total(_e99, _e17, fur_lut, _buffer_sizes);
    float _e102 = fur_positive((2.0 * kept.z) * _e100);
    FurRange _e104 = ranges.inner[3];
    float _e105 = fur_range_kept(_e104);
    float _e110 = fur_positive((2.0 * _e105) * (_e20 - _e23));
    FurRange _e112 = ranges.inner[4];
    float _e113 = fur_range_kept(_e112);
    float _e117 = fur_positive((2.0 * _e113) * _e23);
    type_17 a_10 = type_17 {{_e86, _e94, _e102, _e110, _e117}};
    type_18 _e119 = ranges;
    return FurParts {a_10, {}, _e119};
}

float fur_density_of(
    FurLookups l_3,
    float w_2,
    float cos_theta_i_1
) {
    if (!((w_2 > 0.0))) {
        return 0.0;
    }
    float ms_1 = l_3.ms.inner[0] + (l_3.front * (l_3.ms.inner[1] - l_3.ms.inner[0]));
    float p_5 = (((l_3.m.inner[0] * l_3.n0_.inner[0]) + (l_3.m.inner[1] * l_3.n0_.inner[1])) + (l_3.m.inner[2] * l_3.n0_.inner[2])) + (ms_1 * l_3.n0_.inner[3]);
    float _e38 = fur_pole_keep(cos_theta_i_1);
    float pg = p_5 * _e38;
    float _e44 = fur_positive((pg / w_2) / metal::max(cos_theta_i_1, 0.000001));
    return _e44;
}

float fur_pdf_far(
    float theta_i_3,
    float theta_r_6,
    float phi_2,
    metal::float3 sigma_ca_4,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    bool _e4 = fur_valid(theta_i_3, theta_r_6, phi_2);
    if (!(_e4)) {
        return 0.0;
    }
    FurParts _e7 = fur_parts(theta_r_6, fur_lut, _buffer_sizes);
    float w_6 = (((_e7.a.inner[0] + _e7.a.inner[1]) + _e7.a.inner[2]) + _e7.a.inner[3]) + _e7.a.inner[4];
    FurLookups _e22 = fur_lookups(theta_i_3, theta_r_6, phi_2, sigma_ca_4, fur_lut, _buffer_sizes);
    float _e23 = fur_cos_within_half_pi(theta_i_3);
    float _e24 = fur_density_of(_e22, w_6, _e23);
    return _e24;
}

FurSample fur_sample_far(
    float theta_r_7,
    metal::float3 u_5,
    metal::float3 sigma_ca_5,
    device type_1 const& fur_lut,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurSample out_3 = FurSample {0.0, 0.0, 0.0, {}, metal::float3(0.0), 0u, false};
    bool local_25 = {};
    float total = 0.0;
    uint k_7 = 0u;
    float acc_4 = 0.0;
    uint c_1 = 5u;
    float u0_ = 0.0;
    uint last = 5u;
    uint k_8 = 0u;
    float theta_i_4 = 0.0;
    FurRows nrows = {};
    bool local_26 = {};
    bool _e12 = fur_finite(theta_r_7);
    if (_e12) {
        local_25 = metal::abs(theta_r_7) <= FUR_HALF_PI;
    } else {
        local_25 = false;
    }
    bool _e19 = local_25;
    if (!(_e19)) {
        FurSample _e21 = out_3;
        return _e21;
    }
    FurParts _e22 = fur_parts(theta_r_7, fur_lut, _buffer_sizes);
    uint2 loop_bound_18 = uint2(4294967295u);
    bool loop_init_17 = true;
    while(true) {
        if (metal::all(loop_bound_18 == uint2(0u))) { break; }
        loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
        if (!loop_init_17) {
            uint _e35 = k_7;
            k_7 = _e35 + 1u;
        }
        loop_init_17 = false;
        uint _e27 = k_7;
        if (_e27 < 5u) {
        } else {
            break;
        }
        {
            float _e30 = total;
            uint _e32 = k_7;
            total = _e30 + _e22.a.inner[_e32];
        }
    }
    float _e38 = total;
    if (!((_e38 > 0.0))) {
        FurSample _e42 = out_3;
        return _e42;
    }
    float _e44 = fur_unit(u_5.x);
    float _e45 = total;
    float target_mass = _e44 * _e45;
    uint2 loop_bound_19 = uint2(4294967295u);
    bool loop_init_18 = true;
    while(true) {
        if (metal::all(loop_bound_19 == uint2(0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_18) {
            uint _e77 = k_8;
            k_8 = _e77 + 1u;
        }
        loop_init_18 = false;
        uint _e57 = k_8;
        if (_e57 < 5u) {
        } else {
            break;
        }
        {
            uint _e61 = k_8;
            float wk = _e22.a.inner[_e61];
            if (!((wk > 0.0))) {
                continue;
            }
            uint _e66 = k_8;
            last = _e66;
            float _e67 = acc_4;
            if (target_mass < (_e67 + wk)) {
                uint _e70 = k_8;
                c_1 = _e70;
                float _e71 = acc_4;
                float _e74 = fur_unit((target_mass - _e71) / wk);
                u0_ = _e74;
                break;
            }
            float _e75 = acc_4;
            acc_4 = _e75 + wk;
        }
    }
    uint _e80 = c_1;
    if (_e80 == 5u) {
        uint _e83 = last;
        c_1 = _e83;
        u0_ = 0.99999994;
    }
    float total_weight = (((_e22.a.inner[0] + _e22.a.inner[1]) + _e22.a.inner[2]) + _e22.a.inner[3]) + _e22.a.inner[4];
    float _e99 = u0_;
    bool negative = _e99 < 0.5;
    uint _e104 = c_1;
    if (_e104 < 3u) {
        uint _e107 = c_1;
        FurDensity _e108 = fur_density(_e107, fur_lut, _buffer_sizes);
        FurRows _e112 = fur_rows(_e108, 0u, 0.0, -3.1415927);
        FurAxis _e113 = fur_sum_axis(fur_lut, _buffer_sizes);
        uint _e115 = c_1;
        float _e118 = fur_rows_invert_kept(_e112, _e113, _e22.ranges.inner[_e115], u_5.y, fur_lut, _buffer_sizes);
        theta_i_4 = metal::clamp(_e118 - theta_r_7, -1.5707964, FUR_HALF_PI);
    } else {
        uint _e123 = c_1;
        FurRows _e126 = fur_ms_rows(_e123 - 3u, theta_r_7, fur_lut, _buffer_sizes);
        FurAxis _e127 = fur_ms_i_axis(fur_lut, _buffer_sizes);
        uint _e129 = c_1;
        float _e132 = fur_rows_invert_kept(_e126, _e127, _e22.ranges.inner[_e129], u_5.y, fur_lut, _buffer_sizes);
        theta_i_4 = metal::clamp(_e132, -1.5707964, FUR_HALF_PI);
    }
    uint _e136 = c_1;
    uint family = metal::min(_e136, 3u);
    uint _e142 = fur_word(5u, fur_lut, _buffer_sizes);
    FurAxis _e143 = fur_axis(false, 0.63661975, _e142);
    FurLoc _e145 = fur_locate(_e143, metal::abs(theta_r_7));
    FurDensity _e148 = fur_density(3u + family, fur_lut, _buffer_sizes);
    FurRows _e152 = fur_rows(_e148, _e145.i, _e145.w, 0.0);
    nrows = _e152;
    uint _e154 = c_1;
    if (_e154 >= 3u) {
        uint _e157 = c_1;
        FurRows _e162 = fur_rows_weighted(_e157 - 2u, _e145.i, _e145.w, fur_lut, _buffer_sizes);
        nrows = _e162;
    }
    FurRows _e163 = nrows;
    FurRows _e165 = nrows;
    float _e166 = fur_rows_total(_e165, fur_lut, _buffer_sizes);
    float _e168 = fur_rows_invert_between(_e163, 0.0, _e166, u_5.z, fur_lut, _buffer_sizes);
    float abs_phi_1 = metal::clamp(_e168, 0.0, FUR_PI);
    float _e174 = fur_wrap_angle(negative ? -(abs_phi_1) : abs_phi_1);
    float _e175 = theta_i_4;
    FurLookups _e176 = fur_lookups(_e175, theta_r_7, _e174, sigma_ca_5, fur_lut, _buffer_sizes);
    float _e177 = theta_i_4;
    float _e178 = fur_cos_within_half_pi(_e177);
    float _e179 = fur_density_of(_e176, total_weight, _e178);
    if (_e179 > 0.0) {
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
    float k_19 = metal::max(metal::cos(_e190), 0.0) / _e179;
    float _e195 = theta_i_4;
    out_3 = FurSample {_e195, _e174, _e179, {}, metal::max(_e189.total * k_19, metal::float3(0.0)), family, true};
    FurSample _e203 = out_3;
    return _e203;
}

float fur_dual_half(
    uint h_1,
    device type_1 const& fur_dual,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e7 = fur_dual[FUR_DUAL_HEADER_WORDS + (h_1 >> 1u)];
    metal::float2 pair = float2(as_type<half2>(_e7));
    return ((h_1 & 1u) == 1u) ? pair.y : pair.x;
}

metal::float3 fur_dual_rgb(
    metal::uint3 a_4,
    uint h_2,
    device type_1 const& fur_dual,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint3 n_4 = (a_4 * FUR_DUAL_NODE_HALVES) + metal::uint3(h_2);
    float _e7 = fur_dual_half(n_4.x, fur_dual, _buffer_sizes);
    float _e9 = fur_dual_half(n_4.y, fur_dual, _buffer_sizes);
    float _e11 = fur_dual_half(n_4.z, fur_dual, _buffer_sizes);
    return metal::float3(_e7, _e9, _e11);
}

metal::float3 fur_dual_sigma_node(
    metal::uint3 k_9
) {
    metal::float3 v_3 = (static_cast<metal::float3>(k_9) / metal::float3(15.0)) * 0.997009;
    return metal::select((FUR_DUAL_KNEE * v_3) / (metal::float3(1.0) - v_3), metal::float3(1000.0), k_9 >= metal::uint3(15u));
}

FurDualColour fur_dual_locate(
    metal::float3 sigma_in
) {
    metal::uint3 k_10 = {};
    metal::float3 w_3 = {};
    metal::bool3 _e9 = fur_is_nan3_(sigma_in);
    metal::float3 s_4 = metal::select(metal::min(metal::max(sigma_in, metal::float3(0.0)), metal::float3(1000.0)), metal::float3(0.0), _e9);
    metal::float3 coord = metal::min((s_4 / (s_4 + metal::float3(3.0))) / metal::float3(0.997009), metal::float3(1.0));
    metal::float3 u_9 = metal::clamp(coord * 15.0, metal::float3(0.0), metal::float3(15.0));
    k_10 = metal::min(naga_f2u32(u_9), metal::uint3(14u));
    metal::uint3 _e32 = k_10;
    metal::float3 _e33 = fur_dual_sigma_node(_e32);
    metal::float3 lo_4 = metal::sqrt(_e33);
    metal::uint3 _e35 = k_10;
    metal::float3 _e39 = fur_dual_sigma_node(_e35 + metal::uint3(1u));
    metal::float3 hi_3 = metal::sqrt(_e39);
    w_3 = metal::clamp((metal::sqrt(s_4) - lo_4) / (hi_3 - lo_4), metal::float3(0.0), metal::float3(1.0));
    metal::float3 _e51 = w_3;
    metal::float3 _e54 = w_3;
    metal::bool3 _e55 = fur_is_nan3_(_e54);
    metal::float3 _e56 = w_3;
    w_3 = metal::select(_e51, metal::float3(0.0), _e55 | (_e56 < metal::float3(0.0001)));
    metal::float3 _e62 = w_3;
    metal::uint3 _e66 = k_10;
    metal::bool3 up = (_e62 > metal::float3(0.9999)) & ((_e66 + metal::uint3(2u)) < metal::uint3(16u));
    metal::uint3 _e74 = k_10;
    metal::uint3 _e75 = k_10;
    k_10 = metal::select(_e74, _e75 + metal::uint3(1u), up);
    metal::float3 _e80 = w_3;
    w_3 = metal::select(_e80, metal::float3(0.0), up);
    metal::float3 _e84 = w_3;
    metal::float3 _e87 = w_3;
    w_3 = metal::select(_e84, metal::float3(1.0), _e87 > metal::float3(0.9999));
    metal::uint3 _e92 = k_10;
    metal::float3 _e93 = w_3;
    return FurDualColour {_e92, _e93};
}

bool fur_is_nan(
    float x_10
) {
    return (as_type<uint>(x_10) & 2147483647u) > 2139095040u;
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

FurLoc fur_dual_theta(
    float theta
) {
    float t_8 = {};
    t_8 = ((theta + FUR_HALF_PI) * FUR_DUAL_THETA_SCALE) - 0.5;
    float _e8 = t_8;
    float _e9 = t_8;
    t_8 = (_e9 > 0.0) ? _e8 : 0.0;
    float _e14 = t_8;
    t_8 = metal::min(_e14, 63.0);
    float _e17 = t_8;
    uint k_20 = metal::min(naga_f2u32(_e17), 62u);
    float _e21 = t_8;
    return FurLoc {k_20, _e21 - static_cast<float>(k_20)};
}

metal::float3 fur_dual_node(
    metal::uint3 a_5,
    uint k_11,
    uint f_3,
    device type_1 const& fur_dual,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 _e6 = fur_dual_rgb(a_5, (k_11 * FUR_DUAL_FIELDS) + f_3, fur_dual, _buffer_sizes);
    return _e6;
}

metal::float3 fur_dual_field(
    FurLoc l_4,
    uint f_4,
    device type_1 const& fur_dual,
    thread FurDualColour& fur_dual_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint3 lo_5 = fur_dual_at.node;
    metal::float3 _e6 = fur_dual_node(lo_5, l_4.i, f_4, fur_dual, _buffer_sizes);
    metal::float3 _e10 = fur_dual_node(lo_5, l_4.i + 1u, f_4, fur_dual, _buffer_sizes);
    metal::float3 _e15 = fur_dual_node(lo_5 + metal::uint3(1u), l_4.i, f_4, fur_dual, _buffer_sizes);
    metal::float3 _e22 = fur_dual_node(lo_5 + metal::uint3(1u), l_4.i + 1u, f_4, fur_dual, _buffer_sizes);
    metal::float3 v0_10 = _e6 + ((_e10 - _e6) * l_4.w);
    metal::float3 v1_10 = _e15 + ((_e22 - _e15) * l_4.w);
    metal::float3 _e34 = fur_dual_at.w;
    return v0_10 + ((v1_10 - v0_10) * _e34);
}

metal::float3 fur_dual_ng_at(
    metal::uint3 a_6,
    uint g_5,
    FurLoc l_5,
    FurLoc p,
    device type_1 const& fur_dual,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint row0_ = (((g_5 * FUR_DUAL_THETA_NODES) + l_5.i) * FUR_DUAL_PHI_NODES) + p.i;
    uint row1_ = row0_ + FUR_DUAL_PHI_NODES;
    metal::float3 _e16 = fur_dual_rgb(a_6, FUR_DUAL_NG_START + row0_, fur_dual, _buffer_sizes);
    metal::float3 _e21 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row0_) + 1u, fur_dual, _buffer_sizes);
    metal::float3 _e24 = fur_dual_rgb(a_6, FUR_DUAL_NG_START + row1_, fur_dual, _buffer_sizes);
    metal::float3 _e29 = fur_dual_rgb(a_6, (FUR_DUAL_NG_START + row1_) + 1u, fur_dual, _buffer_sizes);
    float w_7 = l_5.w;
    float v_4 = p.w;
    return (((((1.0 - w_7) * (1.0 - v_4)) * _e16) + (((1.0 - w_7) * v_4) * _e21)) + ((w_7 * (1.0 - v_4)) * _e24)) + ((w_7 * v_4) * _e29);
}

metal::float3 fur_dual_ng(
    uint g_6,
    FurLoc l_6,
    FurLoc p_1,
    device type_1 const& fur_dual,
    thread FurDualColour& fur_dual_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint3 _e5 = fur_dual_at.node;
    metal::float3 _e6 = fur_dual_ng_at(_e5, g_6, l_6, p_1, fur_dual, _buffer_sizes);
    metal::uint3 _e9 = fur_dual_at.node;
    metal::float3 _e13 = fur_dual_ng_at(_e9 + metal::uint3(1u), g_6, l_6, p_1, fur_dual, _buffer_sizes);
    metal::float3 _e17 = fur_dual_at.w;
    return _e6 + ((_e13 - _e6) * _e17);
}

metal::float3 fur_rsqrt_newton(
    metal::float3 v_1
) {
    metal::float3 y_2 = {};
    y_2 = as_type<metal::float3>(metal::uint3(1597463174u) - (as_type<metal::uint3>(v_1) >> metal::uint3(1u)));
    metal::float3 h_4 = 0.5 * v_1;
    metal::float3 _e12 = y_2;
    metal::float3 _e13 = y_2;
    metal::float3 _e15 = y_2;
    y_2 = _e12 * (metal::float3(1.5) - ((h_4 * _e13) * _e15));
    metal::float3 _e21 = y_2;
    metal::float3 _e22 = y_2;
    metal::float3 _e24 = y_2;
    y_2 = _e21 * (metal::float3(1.5) - ((h_4 * _e22) * _e24));
    metal::float3 _e30 = y_2;
    metal::float3 _e31 = y_2;
    metal::float3 _e33 = y_2;
    return _e30 * (metal::float3(1.5) - ((h_4 * _e31) * _e33));
}

metal::float3 fur_exp_neg(
    metal::float3 x_in
) {
    metal::float3 p_2 = metal::float3(0.00019875693);
    metal::float3 x_19 = metal::min(metal::max(x_in, metal::float3(0.0)), metal::float3(87.0));
    metal::float3 k_21 = metal::rint(x_19 * FUR_LOG2_E);
    metal::float3 r_16 = ((k_21 * FUR_LN2_HI) - x_19) + (k_21 * FUR_LN2_LO);
    metal::float3 z_1 = r_16 * r_16;
    metal::float3 _e20 = p_2;
    p_2 = (_e20 * r_16) + metal::float3(0.0013981999);
    metal::float3 _e25 = p_2;
    p_2 = (_e25 * r_16) + metal::float3(0.008333452);
    metal::float3 _e30 = p_2;
    p_2 = (_e30 * r_16) + metal::float3(0.041665796);
    metal::float3 _e35 = p_2;
    p_2 = (_e35 * r_16) + metal::float3(0.16666666);
    metal::float3 _e40 = p_2;
    p_2 = (_e40 * r_16) + metal::float3(0.5);
    metal::float3 _e45 = p_2;
    metal::float3 e_1 = ((_e45 * z_1) + r_16) + metal::float3(1.0);
    return metal::select(metal::ldexp(e_1, naga_neg(naga_f2i32(k_21))), metal::float3(0.0), x_in > metal::float3(87.0));
}

metal::float3 fur_erf(
    metal::float3 x_11
) {
    metal::bool3 _e7 = fur_is_nan3_(x_11);
    metal::float3 a_11 = metal::select(metal::min(metal::abs(x_11), metal::float3(10.0)), metal::float3(0.0), _e7);
    metal::float3 p_6 = (((((((((((FUR_ERF_A6_ * a_11) + metal::float3(0.0002765672)) * a_11) + metal::float3(0.0001520143)) * a_11) + metal::float3(0.009270527)) * a_11) + metal::float3(0.04228201)) * a_11) + metal::float3(0.07052308)) * a_11) + metal::float3(1.0);
    metal::float3 p2_ = p_6 * p_6;
    metal::float3 p4_ = p2_ * p2_;
    metal::float3 p8_ = p4_ * p4_;
    metal::float3 e_2 = metal::float3(1.0) - (metal::float3(1.0) / (p8_ * p8_));
    metal::uint3 sign = as_type<metal::uint3>(x_11) & metal::uint3(2147483648u);
    return as_type<metal::float3>(as_type<metal::uint3>(e_2) | sign);
}

metal::float3 fur_dual_between(
    metal::float3 x_12,
    metal::float3 top
) {
    metal::bool3 _e8 = fur_is_nan3_(x_12);
    return metal::select(metal::min(metal::max(x_12, metal::float3(0.0)), top), metal::float3(0.0), _e8);
}

metal::float3 fur_dual_gauss(
    metal::float3 d_6,
    metal::float3 v_in,
    float theta_i_5
) {
    metal::float3 v_5 = metal::clamp(v_in, metal::float3(0.000003), metal::float3(1000000000000000000000000000000.0));
    metal::float3 _e8 = fur_rsqrt_newton(v_5);
    metal::float3 z_2 = d_6 * _e8;
    metal::float3 _e13 = fur_exp_neg((0.5 * z_2) * z_2);
    metal::float3 g_8 = (_e13 * _e8) * FUR_INV_SQRT_TAU;
    metal::float3 centre = ((d_6 - metal::float3(theta_i_5)) * _e8) * FUR_FRAC_1_SQRT_2_;
    metal::float3 half_range = (FUR_HALF_PI * _e8) * FUR_FRAC_1_SQRT_2_;
    metal::float3 _e27 = fur_erf(centre + half_range);
    metal::float3 _e29 = fur_erf(centre - half_range);
    metal::float3 mass_1 = 0.5 * (_e27 - _e29);
    return g_8 / metal::max(mass_1, metal::float3(0.05));
}

metal::float3 fur_dual_power(
    metal::float3 log2_mu,
    float k_12
) {
    metal::float3 _e6 = fur_exp_neg((-(k_12) * FUR_LN2_) * log2_mu);
    return _e6;
}

metal::float3 fur_reflectance_squared(
    metal::float3 mu,
    metal::float3 t_9
) {
    metal::float3 den_1 = mu * (metal::float3(1.0) - (t_9 * mu));
    metal::float3 _e14 = fur_dual_between((mu - t_9) / metal::max(den_1, metal::float3(0.000001)), metal::float3(1.0));
    return metal::select(metal::float3(0.0), _e14, den_1 > metal::float3(0.000001));
}

metal::float3 fur_downward_flux(
    metal::float3 mu_n,
    metal::float3 mu_2m,
    metal::float3 rho2_
) {
    metal::float3 num = metal::float3(1.0) - (rho2_ * mu_2m);
    metal::float3 den_2 = metal::float3(1.0) - (((rho2_ * mu_n) * mu_n) * mu_2m);
    metal::float3 d_9 = mu_n * (num / metal::max(den_2, metal::float3(0.000001)));
    metal::float3 _e18 = fur_dual_between(d_9, mu_n);
    return metal::select(mu_n, _e18, den_2 > metal::float3(0.000001));
}

metal::float3 fur_backscatter_factor(
    metal::float3 rho2_1,
    metal::float3 mu_1,
    metal::float3 mu_2m_1
) {
    metal::float3 tiny = metal::float3(0.000001);
    metal::float3 g_den = metal::float3(1.0) - (rho2_1 * mu_2m_1);
    metal::float3 _e16 = fur_dual_between((metal::float3(1.0) - mu_2m_1) / metal::max(g_den, tiny), metal::float3(1.0));
    return metal::select(metal::float3(1.0), _e16, g_den > tiny) / metal::max(mu_1, tiny);
}

metal::float3 fur_dual_coat_node(
    metal::uint3 n_1,
    uint k_13,
    device type_1 const& fur_dual,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 _e3 = fur_dual_node(n_1, k_13, FUR_DUAL_LOG2_DECAY, fur_dual, _buffer_sizes);
    metal::float3 _e5 = fur_dual_node(n_1, k_13, FUR_DUAL_A_F2_, fur_dual, _buffer_sizes);
    metal::float3 a_12 = metal::clamp(_e5, metal::float3(0.0), metal::float3(1.0));
    metal::float3 _e12 = fur_dual_power(_e3, 1.0);
    metal::float3 _e16 = fur_rsqrt_newton(metal::max(a_12, metal::float3(0.000000000000000000000000000001)));
    metal::float3 t_16 = a_12 * _e16;
    metal::float3 _e18 = fur_reflectance_squared(_e12, t_16);
    return _e18;
}

metal::float3 fur_dual_coat(
    FurLoc l_7,
    device type_1 const& fur_dual,
    thread FurDualColour& fur_dual_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint3 lo_6 = fur_dual_at.node;
    metal::float3 _e5 = fur_dual_coat_node(lo_6, l_7.i, fur_dual, _buffer_sizes);
    metal::float3 _e9 = fur_dual_coat_node(lo_6, l_7.i + 1u, fur_dual, _buffer_sizes);
    metal::float3 _e14 = fur_dual_coat_node(lo_6 + metal::uint3(1u), l_7.i, fur_dual, _buffer_sizes);
    metal::float3 _e21 = fur_dual_coat_node(lo_6 + metal::uint3(1u), l_7.i + 1u, fur_dual, _buffer_sizes);
    metal::float3 rho0_ = _e5 + ((_e9 - _e5) * l_7.w);
    metal::float3 rho1_ = _e14 + ((_e21 - _e14) * l_7.w);
    metal::float3 _e33 = fur_dual_at.w;
    return rho0_ + ((rho1_ - rho0_) * _e33);
}

float fur_dual_clean(
    float x_13,
    float top_1
) {
    bool local_27 = {};
    bool _e3 = fur_is_nan(x_13);
    if (!(_e3)) {
        local_27 = x_13 > 0.0;
    } else {
        local_27 = false;
    }
    bool _e10 = local_27;
    return _e10 ? metal::min(x_13, top_1) : 0.0;
}

float fur_dual_below(
    float x_14
) {
    bool local_28 = {};
    bool _e2 = fur_is_nan(x_14);
    float deep = _e2 ? FUR_DUAL_MAX_FIBERS : 0.0;
    bool _e9 = fur_is_nan(x_14);
    if (!(_e9)) {
        local_28 = x_14 >= 0.0;
    } else {
        local_28 = false;
    }
    bool _e16 = local_28;
    return _e16 ? metal::min(x_14 + FUR_DUAL_LINE_SAMPLE_OFFSET, FUR_DUAL_MAX_FIBERS) : deep;
}

float fur_dual_below_at_incidence(
    float count_on_line,
    float cos_to_skin
) {
    bool local_29 = {};
    bool local_30 = {};
    bool local_31 = {};
    float skin_layers = (FUR_DUAL_DIFFUSIVITY * metal::min(metal::abs(cos_to_skin), 1.0)) * (count_on_line + FUR_DUAL_LINE_SAMPLE_OFFSET);
    float as_count = metal::max(skin_layers - FUR_DUAL_LINE_SAMPLE_OFFSET, 0.0);
    bool _e14 = fur_is_nan(count_on_line);
    if (!(_e14)) {
        local_29 = count_on_line >= 0.0;
    } else {
        local_29 = false;
    }
    bool _e21 = local_29;
    if (_e21) {
        local_30 = count_on_line < FUR_DUAL_MAX_FIBERS;
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
    return known ? as_count : count_on_line;
}

float fur_dual_forward_density_at_incidence(
    float d_f,
    float cos_to_skin_1
) {
    float scaled = (d_f * FUR_DUAL_DIFFUSIVITY) * metal::min(metal::abs(cos_to_skin_1), 1.0);
    bool _e8 = fur_is_nan(cos_to_skin_1);
    return _e8 ? d_f : scaled;
}

metal::float3 fur_eval_dual(
    float theta_i_6,
    float theta_r_8,
    float phi_in_1,
    float fibers,
    float fibers_below,
    float d_f_in,
    float d_b_in,
    metal::float3 sigma_ca_6,
    device type_1 const& fur_dual,
    thread FurDualColour& fur_dual_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float3 out_4 = {};
    float p_3 = {};
    metal::float3 f_s = {};
    uint g_7 = 0u;
    FurDualColour _e9 = fur_dual_locate(sigma_ca_6);
    fur_dual_at = _e9;
    metal::float3 zero = metal::float3(0.0);
    bool _e12 = fur_valid(theta_i_6, theta_r_8, phi_in_1);
    if (!(_e12)) {
        return zero;
    }
    float _e15 = fur_dual_clean(fibers, FUR_DUAL_MAX_FIBERS);
    float _e16 = fur_dual_below(fibers_below);
    float _e18 = fur_dual_clean(d_f_in, FUR_DUAL_MAX_DENSITY);
    float _e20 = fur_dual_clean(d_b_in, FUR_DUAL_MAX_DENSITY);
    float x_20 = theta_i_6 + theta_r_8;
    float _e22 = fur_cos_within_half_pi(theta_i_6);
    float inv_cos2_1 = 1.0 / metal::max(_e22 * _e22, FUR_MIN_COS2_);
    float direct = metal::clamp(1.0 - _e15, 0.0, 1.0);
    FurLoc _e33 = fur_dual_theta(theta_r_8);
    float _e34 = fur_wrap_angle(phi_in_1);
    float abs_phi_2 = metal::abs(_e34);
    metal::float3 _e41 = fur_dual_field(_e33, (abs_phi_2 < FUR_HALF_PI) ? FUR_DUAL_BACK : FUR_DUAL_FRONT, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 _e43 = fur_dual_field(_e33, FUR_DUAL_LOG2_DECAY, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 _e45 = fur_dual_field(_e33, FUR_DUAL_A_F2_, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 _e47 = fur_dual_power(_e43, 1.0);
    metal::float3 _e50 = fur_dual_power(_e43, 2.0 * _e16);
    metal::float3 _e51 = fur_dual_coat(_e33, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 _e52 = fur_backscatter_factor(_e51, _e47, _e50);
    metal::float3 half_energy = _e41 * _e52;
    metal::float3 _e55 = fur_dual_field(_e33, FUR_DUAL_SIGMA_B0_, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 _e57 = fur_dual_field(_e33, FUR_DUAL_DELTA_B, fur_dual, fur_dual_at, _buffer_sizes);
    metal::float3 d_back = metal::float3(x_20) - _e57;
    metal::float3 s_b = (metal::float3(1.0) + (_e20 * _e45)) * _e55;
    metal::float3 v_back = s_b * s_b;
    float back_scale = (_e20 * inv_cos2_1) / FUR_PI;
    out_4 = zero;
    if (direct > 0.0) {
        metal::float3 _e74 = fur_dual_gauss(d_back, v_back, theta_i_6);
        out_4 = ((direct * back_scale) * half_energy) * _e74;
    }
    if (_e15 > 0.0) {
        FurLoc _e79 = fur_dual_theta(-(theta_i_6));
        metal::float3 _e81 = fur_dual_field(_e79, FUR_DUAL_LOG2_DECAY, fur_dual, fur_dual_at, _buffer_sizes);
        metal::float3 _e83 = fur_dual_field(_e79, FUR_DUAL_BETA_F, fur_dual, fur_dual_at, _buffer_sizes);
        metal::float3 _e84 = fur_dual_power(_e81, _e15);
        metal::float3 _e87 = fur_dual_power(_e81, 2.0 * _e16);
        metal::float3 _e88 = fur_dual_coat(_e79, fur_dual, fur_dual_at, _buffer_sizes);
        metal::float3 _e89 = fur_downward_flux(_e84, _e87, _e88);
        metal::float3 spread = metal::max(_e89 - metal::float3(direct), zero) * _e18;
        if (metal::any(spread > zero)) {
            metal::float3 s2f = (_e15 * _e83) * _e83;
            p_3 = abs_phi_2 * FUR_DUAL_PHI_SCALE;
            float _e101 = p_3;
            float _e104 = p_3;
            p_3 = (_e104 > 0.0) ? metal::min(_e101, 31.0) : 0.0;
            float _e109 = p_3;
            uint j_7 = metal::min(naga_f2u32(_e109), 30u);
            float _e113 = p_3;
            FurLoc at_phi = FurLoc {j_7, _e113 - static_cast<float>(j_7)};
            f_s = zero;
            uint2 loop_bound_20 = uint2(4294967295u);
            bool loop_init_19 = true;
            while(true) {
                if (metal::all(loop_bound_20 == uint2(0u))) { break; }
                loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
                if (!loop_init_19) {
                    uint _e141 = g_7;
                    g_7 = _e141 + 1u;
                }
                loop_init_19 = false;
                uint _e120 = g_7;
                if (_e120 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e124 = g_7;
                    metal::float3 _e126 = fur_dual_field(_e33, FUR_DUAL_MEAN + _e124, fur_dual, fur_dual_at, _buffer_sizes);
                    uint _e128 = g_7;
                    metal::float3 _e130 = fur_dual_field(_e33, FUR_DUAL_SD + _e128, fur_dual, fur_dual_at, _buffer_sizes);
                    uint _e131 = g_7;
                    metal::float3 _e132 = fur_dual_ng(_e131, _e33, at_phi, fur_dual, fur_dual_at, _buffer_sizes);
                    metal::float3 v_6 = (_e130 * _e130) + s2f;
                    metal::float3 _e135 = f_s;
                    metal::float3 _e138 = fur_dual_gauss(metal::float3(x_20) - _e126, v_6, theta_i_6);
                    f_s = _e135 + (_e132 * _e138);
                }
            }
            metal::float3 _e145 = fur_dual_gauss(d_back, v_back + s2f, theta_i_6);
            metal::float3 _e146 = out_4;
            metal::float3 _e147 = f_s;
            out_4 = _e146 + (spread * ((_e147 * inv_cos2_1) + ((back_scale * half_energy) * _e145)));
        }
    }
    float _e155 = out_4.x;
    bool _e156 = fur_finite(_e155);
    float _e158 = out_4.y;
    bool _e159 = fur_finite(_e158);
    float _e161 = out_4.z;
    bool _e162 = fur_finite(_e161);
    metal::bool3 finite = metal::bool3(_e156, _e159, _e162);
    metal::float3 _e164 = out_4;
    metal::float3 _e165 = out_4;
    return metal::select(zero, _e164, finite & (_e165 > zero));
}

metal::float3 fur_eval_dual_dirs(
    metal::float3 wi_2,
    metal::float3 wr_2,
    metal::float3 u_6,
    float fibers_1,
    float fibers_below_1,
    float d_f_1,
    float d_b,
    metal::float3 sigma_ca_7,
    device type_1 const& fur_dual,
    thread FurDualColour& fur_dual_at,
    constant _mslBufferSizes& _buffer_sizes
) {
    FurDirAngles _e8 = fur_angles_from_dirs(wi_2, wr_2, u_6);
    if (!(_e8.ok)) {
        return metal::float3(0.0);
    }
    metal::float3 _e16 = fur_eval_dual(_e8.theta_i, _e8.theta_r, _e8.phi, fibers_1, fibers_below_1, d_f_1, d_b, sigma_ca_7, fur_dual, fur_dual_at, _buffer_sizes);
    return _e16;
}

float fur_coat_sigma_at(
    float x_15
) {
    float x2_1 = x_15 * x_15;
    return metal::clamp(x2_1 / metal::max(1.0 - x2_1, 0.000000000001), 0.0, FUR_SIGMA_CA_MAX);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

float fur_coat_sigma_for(
    type_19 table,
    float c_2
) {
    type_19 nodes_2 = {};
    uint k_14 = 0u;
    float t_10 = {};
    nodes_2 = table;
    float _e5 = nodes_2.inner[0].x;
    if (c_2 >= _e5) {
        return 0.0;
    }
    uint2 loop_bound_21 = uint2(4294967295u);
    bool loop_init_20 = true;
    while(true) {
        if (metal::all(loop_bound_21 == uint2(0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        if (!loop_init_20) {
            uint _e51 = k_14;
            k_14 = _e51 + 1u;
        }
        loop_init_20 = false;
        uint _e10 = k_14;
        if (_e10 < 23u) {
        } else {
            break;
        }
        {
            uint _e13 = k_14;
            uint _e17 = k_14;
            float hi_4 = nodes_2.inner[naga_div(_e13, 4u)][naga_mod(_e17, 4u)];
            uint _e22 = k_14;
            uint _e28 = k_14;
            float lo_7 = nodes_2.inner[naga_div(_e22 + 1u, 4u)][naga_mod(_e28 + 1u, 4u)];
            if (c_2 >= lo_7) {
                t_10 = 0.0;
                if (hi_4 > lo_7) {
                    t_10 = (hi_4 - c_2) / (hi_4 - lo_7);
                }
                uint _e42 = k_14;
                float _e44 = t_10;
                float x_21 = ((static_cast<float>(_e42) + _e44) / 23.0) * FUR_COAT_AXIS_END;
                float _e50 = fur_coat_sigma_at(x_21);
                return _e50;
            }
        }
    }
    return FUR_SIGMA_CA_MAX;
}

metal::float3 fur_absorption_from_colour(
    type_19 table_1,
    metal::float3 colour
) {
    float _e3 = fur_coat_sigma_for(table_1, colour.x);
    float _e5 = fur_coat_sigma_for(table_1, colour.y);
    float _e7 = fur_coat_sigma_for(table_1, colour.z);
    return metal::float3(_e3, _e5, _e7);
}

void fur_store(
    uint q,
    FurFamilies f_5,
    device type_21& fur_results,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint k_15 = 0u;
    uint base_1 = 16u * q;
    type_22 parts = type_22 {{f_5.r, f_5.tt, f_5.trt, f_5.scattered, f_5.total}};
    uint2 loop_bound_22 = uint2(4294967295u);
    bool loop_init_21 = true;
    while(true) {
        if (metal::all(loop_bound_22 == uint2(0u))) { break; }
        loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
        if (!loop_init_21) {
            uint _e46 = k_15;
            k_15 = _e46 + 1u;
        }
        loop_init_21 = false;
        uint _e12 = k_15;
        if (_e12 < 5u) {
        } else {
            break;
        }
        {
            uint _e17 = k_15;
            uint _e21 = k_15;
            fur_results[base_1 + (3u * _e17)] = parts.inner[_e21].x;
            uint _e26 = k_15;
            uint _e32 = k_15;
            fur_results[(base_1 + (3u * _e26)) + 1u] = parts.inner[_e32].y;
            uint _e37 = k_15;
            uint _e43 = k_15;
            fur_results[(base_1 + (3u * _e37)) + 2u] = parts.inner[_e43].z;
        }
    }
    fur_results[base_1 + 15u] = 0.0;
    return;
}

void fur_store_rgb(
    uint q_1,
    metal::float3 v_2,
    device type_21& fur_results,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint k_16 = 3u;
    uint base_2 = 16u * q_1;
    fur_results[base_2] = v_2.x;
    fur_results[base_2 + 1u] = v_2.y;
    fur_results[base_2 + 2u] = v_2.z;
    uint2 loop_bound_23 = uint2(4294967295u);
    bool loop_init_22 = true;
    while(true) {
        if (metal::all(loop_bound_23 == uint2(0u))) { break; }
        loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
        if (!loop_init_22) {
            uint _e27 = k_16;
            k_16 = _e27 + 1u;
        }
        loop_init_22 = false;
        uint _e19 = k_16;
        if (_e19 < 16u) {
        } else {
            break;
        }
        {
            uint _e23 = k_16;
            fur_results[base_2 + _e23] = 0.0;
        }
    }
    return;
}

struct fur_eval_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_eval_main(
  metal::uint3 id [[thread_position_in_grid]]
, device type_1 const& fur_lut [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint q_2 = id.x;
    if (((2u * q_2) + 1u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 a_13 = fur_queries[2u * q_2];
    metal::float4 _e23 = fur_queries[(2u * q_2) + 1u];
    FurFamilies _e25 = fur_eval_far(a_13.x, a_13.y, a_13.z, _e23.xyz, fur_lut, _buffer_sizes);
    fur_store(q_2, _e25, fur_results, _buffer_sizes);
    return;
}


struct fur_eval_dirs_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_eval_dirs_main(
  metal::uint3 id_1 [[thread_position_in_grid]]
, device type_1 const& fur_lut [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint q_3 = id_1.x;
    if (((3u * q_3) + 2u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 wi_3 = fur_queries[3u * q_3];
    metal::float4 wr_3 = fur_queries[(3u * q_3) + 1u];
    metal::float4 u_10 = fur_queries[(3u * q_3) + 2u];
    FurFamilies _e35 = fur_eval_far_dirs(wi_3.xyz, wr_3.xyz, u_10.xyz, metal::float3(wi_3.w, wr_3.w, u_10.w), fur_lut, _buffer_sizes);
    fur_store(q_3, _e35, fur_results, _buffer_sizes);
    return;
}


struct fur_sample_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_sample_main(
  metal::uint3 id_2 [[thread_position_in_grid]]
, device type_1 const& fur_lut [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint q_4 = id_2.x;
    if (((2u * q_4) + 1u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 a_14 = fur_queries[2u * q_4];
    metal::float4 _e22 = fur_queries[(2u * q_4) + 1u];
    FurSample _e24 = fur_sample_far(a_14.x, a_14.yzw, _e22.xyz, fur_lut, _buffer_sizes);
    uint base_3 = 16u * q_4;
    fur_results[base_3] = _e24.theta_i;
    fur_results[base_3 + 1u] = _e24.phi;
    fur_results[base_3 + 2u] = _e24.pdf;
    fur_results[base_3 + 3u] = _e24.weight[0];
    fur_results[base_3 + 4u] = _e24.weight[1];
    fur_results[base_3 + 5u] = _e24.weight[2];
    fur_results[base_3 + 6u] = static_cast<float>(_e24.family);
    fur_results[base_3 + 7u] = _e24.ok ? 1.0 : 0.0;
    return;
}


struct fur_pdf_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_pdf_main(
  metal::uint3 id_3 [[thread_position_in_grid]]
, device type_1 const& fur_lut [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint q_5 = id_3.x;
    if (((2u * q_5) + 1u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 a_15 = fur_queries[2u * q_5];
    metal::float4 _e27 = fur_queries[(2u * q_5) + 1u];
    float _e29 = fur_pdf_far(a_15.x, a_15.y, a_15.z, _e27.xyz, fur_lut, _buffer_sizes);
    fur_results[16u * q_5] = _e29;
    return;
}


struct fur_dual_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_dual_main(
  metal::uint3 id_4 [[thread_position_in_grid]]
, device type_1 const& fur_dual [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    FurDualColour fur_dual_at = {};
    uint q_6 = id_4.x;
    if (((3u * q_6) + 2u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 a_16 = fur_queries[3u * q_6];
    metal::float4 d_10 = fur_queries[(3u * q_6) + 1u];
    metal::float4 sigma = fur_queries[(3u * q_6) + 2u];
    metal::float3 _e36 = fur_eval_dual(a_16.x, a_16.y, a_16.z, a_16.w, d_10.z, d_10.x, d_10.y, sigma.xyz, fur_dual, fur_dual_at, _buffer_sizes);
    fur_store_rgb(q_6, _e36, fur_results, _buffer_sizes);
    return;
}


struct fur_dual_dirs_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_dual_dirs_main(
  metal::uint3 id_5 [[thread_position_in_grid]]
, device type_1 const& fur_dual [[user(fake0)]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    FurDualColour fur_dual_at = {};
    uint q_7 = id_5.x;
    if (((4u * q_7) + 3u) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 wi_4 = fur_queries[4u * q_7];
    metal::float4 wr_4 = fur_queries[(4u * q_7) + 1u];
    metal::float4 u_11 = fur_queries[(4u * q_7) + 2u];
    metal::float4 below = fur_queries[(4u * q_7) + 3u];
    metal::float3 _e43 = fur_eval_dual_dirs(wi_4.xyz, wr_4.xyz, u_11.xyz, wi_4.w, below.x, wr_4.w, u_11.w, below.yzw, fur_dual, fur_dual_at, _buffer_sizes);
    fur_store_rgb(q_7, _e43, fur_results, _buffer_sizes);
    return;
}


struct fur_absorption_mainInput {
};
[[max_total_threads_per_threadgroup(64)]] kernel void fur_absorption_main(
  metal::uint3 id_6 [[thread_position_in_grid]]
, device type_20 const& fur_queries [[user(fake0)]]
, device type_21& fur_results [[user(fake0)]]
, constant _mslBufferSizes& _buffer_sizes [[user(fake0)]]
) {
    uint q_8 = id_6.x;
    if ((6u + q_8) >= (1 + (_buffer_sizes.size3 - 0 - 16) / 16)) {
        return;
    }
    metal::float4 _e9 = fur_queries[0];
    metal::float4 _e12 = fur_queries[1];
    metal::float4 _e15 = fur_queries[2];
    metal::float4 _e18 = fur_queries[3];
    metal::float4 _e21 = fur_queries[4];
    metal::float4 _e24 = fur_queries[5];
    type_19 table_2 = type_19 {{_e9, _e12, _e15, _e18, _e21, _e24}};
    metal::float4 _e30 = fur_queries[6u + q_8];
    metal::float3 _e32 = fur_absorption_from_colour(table_2, _e30.xyz);
    fur_store_rgb(q_8, _e32, fur_results, _buffer_sizes);
    return;
}
