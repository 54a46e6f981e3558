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
const float FUR_PI = 3.1415927;
const float FUR_HALF_PI = 1.5707964;
const float FUR_TAU = 6.2831855;
const float FUR_MIN_COS2_ = 0.0001;
const uint FUR_HEADER_HALVES = 80u;

layout(std430) readonly buffer type_1_block_0Compute { uint _group_0_binding_0_cs[]; };

layout(std430) readonly buffer type_12_block_1Compute { vec4 _group_0_binding_1_cs[]; };

layout(std430) buffer type_13_block_2Compute { float _group_0_binding_2_cs[]; };


FurAxis fur_axis(bool centred, float inv_span, uint nodes) {
    float last = float((nodes - 1u));
    return FurAxis((last * inv_span), (centred ? (0.5 * last) : 0.0), last, nodes);
}

FurLoc fur_locate(FurAxis a, float x) {
    float u_1 = min(max(((x * a.inv_step) + a.offset), 0.0), a.last);
    int i = min(int(u_1), (int(a.nodes) - 2));
    return FurLoc(uint(i), (u_1 - float(i)));
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
    uint _e3 = fur_word((9u + t));
    return (uintBitsToFloat(_e3) * uintBitsToFloat(2004877312u));
}

float fur_cos_within_half_pi(float x_1) {
    float acc = -2.755732e-7;
    float acc_1 = 2.7557319e-6;
    float a_1 = abs(x_1);
    if ((a_1 <= 0.7853982)) {
        float y_2 = (a_1 * a_1);
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
    float r = ((1.5707964 - a_1) + -4.371139e-8);
    float y_3 = (r * r);
    float _e34 = acc_1;
    acc_1 = ((_e34 * y_3) - 0.0001984127);
    float _e38 = acc_1;
    acc_1 = ((_e38 * y_3) + 0.008333334);
    float _e42 = acc_1;
    acc_1 = ((_e42 * y_3) - 0.16666667);
    float _e46 = acc_1;
    return (((_e46 * y_3) * r) + r);
}

float fur_wrap_angle(float x_2) {
    bool local = false;
    bool local_1 = false;
    bool local_2 = false;
    float y = 0.0;
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
    return _e50;
}

FurFamilies fur_zero() {
    vec3 z_2 = vec3(0.0);
    return FurFamilies(z_2, z_2, z_2, z_2, z_2);
}

bool fur_finite(float x_3) {
    return ((floatBitsToUint(x_3) & 2139095040u) != 2139095040u);
}

FurFamilies fur_eval_far(float theta_i, float theta_r, float phi_in) {
    bool local_3 = false;
    bool local_4 = false;
    bool local_5 = false;
    bool local_6 = false;
    float m[3] = float[3](0.0, 0.0, 0.0);
    uint ch = 0u;
    float ms[2] = float[2](0.0, 0.0);
    uint ch_1 = 0u;
    float n[12] = float[12](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    uint ch_2 = 0u;
    vec3 f[4] = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint k_1 = 0u;
    bool _e3 = fur_finite(theta_i);
    if (_e3) {
        bool _e6 = fur_finite(theta_r);
        local_3 = _e6;
    } else {
        local_3 = false;
    }
    bool _e8 = local_3;
    if (_e8) {
        bool _e11 = fur_finite(phi_in);
        local_4 = _e11;
    } else {
        local_4 = false;
    }
    bool _e13 = local_4;
    if (!(!(_e13))) {
        local_5 = (abs(theta_i) > FUR_HALF_PI);
    } else {
        local_5 = true;
    }
    bool _e22 = local_5;
    if (!(_e22)) {
        local_6 = (abs(theta_r) > FUR_HALF_PI);
    } else {
        local_6 = true;
    }
    bool _e30 = local_6;
    if (_e30) {
        FurFamilies _e31 = fur_zero();
        return _e31;
    }
    float _e32 = fur_wrap_angle(phi_in);
    uint _e34 = fur_word(4u);
    uint _e36 = fur_word(5u);
    uint _e38 = fur_word(6u);
    uint _e40 = fur_word(7u);
    uint _e42 = fur_word(8u);
    uint n0_ = (FUR_HEADER_HALVES + (3u * _e34));
    uint s0_ = (n0_ + ((12u * _e38) * _e36));
    float abs_phi = abs(_e32);
    float _e52 = fur_cos_within_half_pi(theta_i);
    float inv_cos2_ = (1.0 / max((_e52 * _e52), FUR_MIN_COS2_));
    FurAxis _e60 = fur_axis(true, 0.15915494, _e34);
    FurLoc _e62 = fur_locate(_e60, (theta_i + theta_r));
    float _e64 = fur_unbias(0u);
    float wm0_ = ((1.0 - _e62.w) * _e64);
    float wm1_ = (_e62.w * _e64);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e98 = ch;
            ch = (_e98 + 1u);
        }
        loop_init = false;
        uint _e74 = ch;
        if ((_e74 < 3u)) {
        } else {
            break;
        }
        {
            uint _e81 = ch;
            float _e83 = fur_half(((FUR_HEADER_HALVES + (3u * _e62.i)) + _e81));
            uint _e90 = ch;
            float _e92 = fur_half(((FUR_HEADER_HALVES + (3u * (_e62.i + 1u))) + _e90));
            uint _e93 = ch;
            m[_e93] = ((wm0_ * _e83) + (wm1_ * _e92));
        }
    }
    FurAxis _e103 = fur_axis(true, 0.31830987, _e42);
    FurLoc _e104 = fur_locate(_e103, theta_r);
    FurAxis _e107 = fur_axis(true, 0.31830987, _e40);
    FurLoc _e108 = fur_locate(_e107, theta_i);
    float _e110 = fur_unbias(2u);
    {
        float ky0_ = ((1.0 - _e104.w) * _e110);
        float ky1_ = (_e104.w * _e110);
        float w0_ = (ky0_ * (1.0 - _e108.w));
        float w1_ = (ky0_ * _e108.w);
        float w2_ = (ky1_ * (1.0 - _e108.w));
        float w3_ = (ky1_ * _e108.w);
        uint i0_ = ((_e104.i * _e40) + _e108.i);
        bool loop_init_1 = true;
        while(true) {
            if (!loop_init_1) {
                uint _e178 = ch_1;
                ch_1 = (_e178 + 1u);
            }
            loop_init_1 = false;
            uint _e136 = ch_1;
            if ((_e136 < 2u)) {
            } else {
                break;
            }
            {
                uint _e142 = ch_1;
                float _e144 = fur_half(((s0_ + (2u * i0_)) + _e142));
                uint _e150 = ch_1;
                float _e152 = fur_half(((s0_ + (2u * (i0_ + 1u))) + _e150));
                uint _e157 = ch_1;
                float _e159 = fur_half(((s0_ + (2u * (i0_ + _e40))) + _e157));
                uint _e166 = ch_1;
                float _e168 = fur_half(((s0_ + (2u * ((i0_ + _e40) + 1u))) + _e166));
                uint _e169 = ch_1;
                ms[_e169] = ((((w0_ * _e144) + (w1_ * _e152)) + (w2_ * _e159)) + (w3_ * _e168));
            }
        }
    }
    float front_w = min((abs_phi * 0.31830987), 1.0);
    float _e186 = ms[0];
    float _e188 = ms[1];
    float _e190 = ms[0];
    float mss = (_e186 + (front_w * (_e188 - _e190)));
    FurAxis _e196 = fur_axis(false, 0.63661975, _e36);
    FurLoc _e198 = fur_locate(_e196, abs(theta_r));
    FurAxis _e201 = fur_axis(false, 0.31830987, _e38);
    FurLoc _e202 = fur_locate(_e201, abs_phi);
    float _e204 = fur_unbias(1u);
    float ny0_ = ((1.0 - _e198.w) * _e204);
    float ny1_ = (_e198.w * _e204);
    float v0_ = (ny0_ * (1.0 - _e202.w));
    float v1_ = (ny0_ * _e202.w);
    float v2_ = (ny1_ * (1.0 - _e202.w));
    float v3_ = (ny1_ * _e202.w);
    uint j0_ = ((_e198.i * _e38) + _e202.i);
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e272 = ch_2;
            ch_2 = (_e272 + 1u);
        }
        loop_init_2 = false;
        uint _e230 = ch_2;
        if ((_e230 < 12u)) {
        } else {
            break;
        }
        {
            uint _e236 = ch_2;
            float _e238 = fur_half(((n0_ + (12u * j0_)) + _e236));
            uint _e244 = ch_2;
            float _e246 = fur_half(((n0_ + (12u * (j0_ + 1u))) + _e244));
            uint _e251 = ch_2;
            float _e253 = fur_half(((n0_ + (12u * (j0_ + _e38))) + _e251));
            uint _e260 = ch_2;
            float _e262 = fur_half(((n0_ + (12u * ((j0_ + _e38) + 1u))) + _e260));
            uint _e263 = ch_2;
            n[_e263] = ((((v0_ * _e238) + (v1_ * _e246)) + (v2_ * _e253)) + (v3_ * _e262));
        }
    }
    float _e276 = m[0];
    float _e278 = m[1];
    float _e280 = m[2];
    float lon[4] = float[4](_e276, _e278, _e280, mss);
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e314 = k_1;
            k_1 = (_e314 + 1u);
        }
        loop_init_3 = false;
        uint _e285 = k_1;
        if ((_e285 < 4u)) {
        } else {
            break;
        }
        {
            uint _e288 = k_1;
            float weight = (lon[_e288] * inv_cos2_);
            uint _e291 = k_1;
            uint _e294 = k_1;
            float _e297 = n[(3u * _e294)];
            uint _e299 = k_1;
            float _e304 = n[((3u * _e299) + 1u)];
            uint _e306 = k_1;
            float _e311 = n[((3u * _e306) + 2u)];
            f[_e291] = (vec3(_e297, _e304, _e311) * weight);
        }
    }
    vec3 _e318 = f[0];
    vec3 _e320 = f[1];
    vec3 _e322 = f[2];
    vec3 _e324 = f[3];
    vec3 _e326 = f[0];
    vec3 _e328 = f[1];
    vec3 _e331 = f[2];
    vec3 _e334 = f[3];
    return FurFamilies(_e318, _e320, _e322, _e324, (((_e326 + _e328) + _e331) + _e334));
}

float fur_asin_r(float z) {
    float p = (z * (0.16666587 + (z * (-0.042743422 + (z * -0.008656363)))));
    float q_1 = (1.0 + (z * -0.70662963));
    return (p / q_1);
}

float fur_asin(float x_4) {
    uint ix = (floatBitsToUint(x_4) & 2147483647u);
    if ((ix >= 1065353216u)) {
        return (sign(x_4) * FUR_HALF_PI);
    }
    if ((ix < 1056964608u)) {
        if ((ix < 964689920u)) {
            return x_4;
        }
        float _e14 = fur_asin_r((x_4 * x_4));
        return (x_4 + (x_4 * _e14));
    }
    float z_3 = ((1.0 - abs(x_4)) * 0.5);
    float s = sqrt(z_3);
    float _e24 = fur_asin_r(z_3);
    float a_2 = (FUR_HALF_PI - (2.0 * (s + (s * _e24))));
    return ((x_4 < 0.0) ? -(a_2) : a_2);
}

float fur_atan(float x_in) {
    float x_5 = 0.0;
    int id_2 = -1;
    x_5 = x_in;
    float _e2 = x_5;
    uint ix_1 = (floatBitsToUint(_e2) & 2147483647u);
    float _e6 = x_5;
    bool negative = (_e6 < 0.0);
    if ((ix_1 >= 1283457024u)) {
        return (negative ? -1.5707963 : 1.5707963);
    }
    if ((ix_1 < 1054867456u)) {
        if ((ix_1 < 964689920u)) {
            float _e20 = x_5;
            return _e20;
        }
    } else {
        float _e21 = x_5;
        x_5 = abs(_e21);
        if ((ix_1 < 1066926080u)) {
            if ((ix_1 < 1060110336u)) {
                float _e27 = x_5;
                float _e32 = x_5;
                x_5 = (((2.0 * _e27) - 1.0) / (2.0 + _e32));
                id_2 = 0;
            } else {
                float _e37 = x_5;
                float _e40 = x_5;
                x_5 = ((_e37 - 1.0) / (_e40 + 1.0));
                id_2 = 1;
            }
        } else {
            if ((ix_1 < 1075576832u)) {
                float _e47 = x_5;
                float _e50 = x_5;
                x_5 = ((_e47 - 1.5) / (1.0 + (1.5 * _e50)));
                id_2 = 2;
            } else {
                float _e57 = x_5;
                x_5 = (-1.0 / _e57);
                id_2 = 3;
            }
        }
    }
    float _e61 = x_5;
    float _e62 = x_5;
    float z_4 = (_e61 * _e62);
    float w = (z_4 * z_4);
    float s1_ = (z_4 * (0.33333328 + (w * (0.14253636 + (w * 0.061687607)))));
    float s2_ = (w * (-0.19999158 + (w * -0.106480174)));
    int _e78 = id_2;
    if ((_e78 < 0)) {
        float _e81 = x_5;
        float _e82 = x_5;
        return (_e81 - (_e82 * (s1_ + s2_)));
    }
    float hi[4] = float[4](0.4636476, 0.7853981, 0.9827937, 1.5707963);
    float lo[4] = float[4](5.0121582e-9, 3.7748947e-8, 3.4473217e-8, 7.5497894e-8);
    int _e96 = id_2;
    float _e98 = x_5;
    int _e101 = id_2;
    float _e104 = x_5;
    float r_1 = (hi[_e96] - (((_e98 * (s1_ + s2_)) - lo[_e101]) - _e104));
    return (negative ? -(r_1) : r_1);
}

float fur_atan2_(float y_1, float x_6) {
    float z_1 = 0.0;
    bool local_7 = false;
    uint bx = floatBitsToUint(x_6);
    uint by = floatBitsToUint(y_1);
    if ((bx == 1065353216u)) {
        float _e6 = fur_atan(y_1);
        return _e6;
    }
    uint m_1 = (((by >> 31u) & 1u) | ((bx >> 30u) & 2u));
    uint ix_2 = (bx & 2147483647u);
    uint iy = (by & 2147483647u);
    if ((iy == 0u)) {
        if ((m_1 < 2u)) {
            return y_1;
        }
        return ((m_1 == 3u) ? -3.1415927 : FUR_PI);
    }
    if ((ix_2 == 0u)) {
        return (((m_1 & 1u) != 0u) ? -1.5707964 : FUR_HALF_PI);
    }
    if (((ix_2 + 218103808u) < iy)) {
        return (((m_1 & 1u) != 0u) ? -1.5707964 : FUR_HALF_PI);
    }
    if (((m_1 & 2u) != 0u)) {
        local_7 = ((iy + 218103808u) < ix_2);
    } else {
        local_7 = false;
    }
    bool _e60 = local_7;
    if (!(_e60)) {
        float _e64 = fur_atan(abs((y_1 / x_6)));
        z_1 = _e64;
    }
    switch(m_1) {
        case 0u: {
            float _e66 = z_1;
            return _e66;
        }
        case 1u: {
            float _e67 = z_1;
            return -(_e67);
        }
        case 2u: {
            float _e70 = z_1;
            return (FUR_PI - (_e70 - -8.742278e-8));
        }
        default: {
            float _e73 = z_1;
            return ((_e73 - -8.742278e-8) - FUR_PI);
        }
    }
}

FurFamilies fur_eval_far_dirs(vec3 wi, vec3 wr, vec3 u) {
    uint k_2 = 0u;
    bool local_8 = false;
    bool local_9 = false;
    bool local_10 = false;
    bool local_11 = false;
    bool local_12 = false;
    bool local_13 = false;
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e27 = k_2;
            k_2 = (_e27 + 1u);
        }
        loop_init_4 = false;
        uint _e5 = k_2;
        if ((_e5 < 3u)) {
        } else {
            break;
        }
        {
            uint _e8 = k_2;
            bool _e10 = fur_finite(wi[_e8]);
            if (_e10) {
                uint _e13 = k_2;
                bool _e15 = fur_finite(wr[_e13]);
                local_8 = _e15;
            } else {
                local_8 = false;
            }
            bool _e17 = local_8;
            if (_e17) {
                uint _e20 = k_2;
                bool _e22 = fur_finite(u[_e20]);
                local_9 = _e22;
            } else {
                local_9 = false;
            }
            bool _e24 = local_9;
            if (!(_e24)) {
                FurFamilies _e26 = fur_zero();
                return _e26;
            }
        }
    }
    float ni = sqrt(dot(wi, wi));
    float nr = sqrt(dot(wr, wr));
    float nu = sqrt(dot(u, u));
    bool _e36 = fur_finite(ni);
    if (_e36) {
        bool _e39 = fur_finite(nr);
        local_10 = _e39;
    } else {
        local_10 = false;
    }
    bool _e41 = local_10;
    if (_e41) {
        bool _e44 = fur_finite(nu);
        local_11 = _e44;
    } else {
        local_11 = false;
    }
    bool _e46 = local_11;
    if (!(_e46)) {
        FurFamilies _e48 = fur_zero();
        return _e48;
    }
    if (!((ni < 1.1754944e-38))) {
        local_12 = (nr < 1.1754944e-38);
    } else {
        local_12 = true;
    }
    bool _e56 = local_12;
    if (!(_e56)) {
        local_13 = (nu < 1.1754944e-38);
    } else {
        local_13 = true;
    }
    bool _e62 = local_13;
    if (_e62) {
        FurFamilies _e63 = fur_zero();
        return _e63;
    }
    vec3 un = (u / vec3(nu));
    float si = (dot(wi, un) / ni);
    float sr = (dot(wr, un) / nr);
    float _e73 = fur_asin(clamp(si, -1.0, 1.0));
    float _e77 = fur_asin(clamp(sr, -1.0, 1.0));
    vec3 pi = ((wi / vec3(ni)) - (si * un));
    vec3 pr = ((wr / vec3(nr)) - (sr * un));
    float _e89 = fur_atan2_(dot(un, cross(pi, pr)), dot(pi, pr));
    FurFamilies _e90 = fur_eval_far(_e73, _e77, _e89);
    return _e90;
}

void fur_store(uint q, FurFamilies f_1) {
    uint k_3 = 0u;
    uint base = (16u * q);
    vec3 parts[5] = vec3[5](f_1.r, f_1.tt, f_1.trt, f_1.scattered, f_1.total);
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e46 = k_3;
            k_3 = (_e46 + 1u);
        }
        loop_init_5 = false;
        uint _e12 = k_3;
        if ((_e12 < 5u)) {
        } else {
            break;
        }
        {
            uint _e17 = k_3;
            uint _e21 = k_3;
            _group_0_binding_2_cs[(base + (3u * _e17))] = parts[_e21].x;
            uint _e26 = k_3;
            uint _e32 = k_3;
            _group_0_binding_2_cs[((base + (3u * _e26)) + 1u)] = parts[_e32].y;
            uint _e37 = k_3;
            uint _e43 = k_3;
            _group_0_binding_2_cs[((base + (3u * _e37)) + 2u)] = parts[_e43].z;
        }
    }
    _group_0_binding_2_cs[(base + 15u)] = 0.0;
    return;
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint q_2 = id.x;
    if ((q_2 >= uint(_group_0_binding_1_cs.length()))) {
        return;
    }
    vec4 a_3 = _group_0_binding_1_cs[q_2];
    FurFamilies _e11 = fur_eval_far(a_3.x, a_3.y, a_3.z);
    fur_store(q_2, _e11);
    return;
}

