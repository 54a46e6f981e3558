// raster.wgsl: fur strands in a vertex/fragment pipeline (docs/engines.md, docs/model.md §13
// "Deep opacity map"). Appended by the `raster` crate to bcsdf-core's fur_bcsdf.wgsl
// (`bcsdf_core::shader::FUR_BCSDF_WGSL`), whose functions it calls: fur_eval_far_dirs
// (single scattering) and fur_eval_dual_dirs (the dual-scattering term), with the .furlut
// words at group 0 binding 0 and the .furdual words at group 0 binding 3.
//
// Passes, in order (all from the same instance buffer, one instance per fiber segment):
//   1. ras_surface_light: the opaque surfaces' depth from the light (the shadow map);
//   2. ras_fiber_light (depth only): the first fiber's depth from the light, per texel;
//   3. ras_fiber_light + ras_dom_layers: every fiber fragment in front of the first
//      surface adds its share of a fiber to one of four depth layers behind that first
//      fiber (additive blending into an Rgba16Float target): the deep opacity map;
//   4. ras_surface_camera + ras_surface_shade, ras_fiber_camera + ras_fiber_shade: the
//      image (4x MSAA; alpha is 1 on fur, 0 elsewhere, so the resolved alpha is the
//      fur's coverage of the pixel).

struct RasFrame {
    // World to camera clip space.
    view_proj: mat4x4<f32>,
    // World to the light's orthographic clip space (z: depth from the light, 0..1).
    light_proj: mat4x4<f32>,
    // xyz: the eye.
    eye: vec4<f32>,
    // xyz: unit vector toward the key light; w: world units per unit of light depth.
    light_axis: vec4<f32>,
    // rgb: the key light's irradiance normal to its axis; w: the light map's side in texels.
    key: vec4<f32>,
    // rgb: the uniform sky's radiance; w: the world size of one light-map texel.
    sky: vec4<f32>,
    // rgb: the floor's albedo; w: half the floor's side (its centre is floor_at.xyz).
    floor_albedo: vec4<f32>,
    // xyz: the floor's centre (the plane y = floor_at.y); w: 1 if there is a floor.
    floor_at: vec4<f32>,
    // xyz: the ends of deep opacity layers 0, 1, 2 behind the first fiber (world units; the
    // last layer is open); w: the depth bias of a fur fragment, in fiber radii.
    dom: vec4<f32>,
    // x, y: the density factors d_f, d_b; z: the surfaces' shadow bias (world units); w: 1 to
    // write the fiber counts (n, m, total) instead of the fur's radiance.
    dual: vec4<f32>,
    // rgb: the skin's albedo (the surface the strands grow from).
    skin_albedo: vec4<f32>,
}

@group(1) @binding(0) var<uniform> ras: RasFrame;
@group(1) @binding(1) var ras_shadow: texture_depth_2d;
@group(1) @binding(2) var ras_first: texture_depth_2d;
@group(1) @binding(3) var ras_layers: texture_2d<f32>;
// The fiber's directional albedo under uniform light, rgb per theta_r node (centred nodes
// over [-pi/2, pi/2]), for the sky and floor light (docs/engines.md).
@group(1) @binding(4) var<storage, read> ras_albedo: array<vec4<f32>>;

// One fiber segment: (p0, r0), (p1, r1), (sigma_ca rgb, _), (skin normal at the root, the whole
// coat's count along it at the strand's root), and the coat above both ends (raster::coat:
// fibers above along the skin normal and across its tangent plane, at p0 then p1).
struct RasSegment {
    @location(0) a: vec4<f32>,
    @location(1) b: vec4<f32>,
    @location(2) colour: vec4<f32>,
    @location(3) skin: vec4<f32>,
    @location(4) coat: vec4<f32>,
}

// One surface vertex.
struct RasVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
}

// The ribbon's corner for vertex v of its two triangles: (along, side).
fn ras_corner(v: u32) -> vec2<f32> {
    var c = array<vec2<f32>, 6>(
        vec2<f32>(0.0, -1.0), vec2<f32>(0.0, 1.0), vec2<f32>(1.0, -1.0),
        vec2<f32>(1.0, -1.0), vec2<f32>(0.0, 1.0), vec2<f32>(1.0, 1.0),
    );
    return c[v];
}

// A unit vector across the segment `t`, perpendicular to `facing` too (0 if degenerate).
fn ras_across(t: vec3<f32>, facing: vec3<f32>) -> vec3<f32> {
    let s = cross(t, facing);
    let l = length(s);
    return select(vec3<f32>(0.0), s / l, l > 1e-12);
}

// ---- Passes 1-3: from the light ----

@vertex
fn ras_surface_light(v: RasVertex) -> @builtin(position) vec4<f32> {
    return ras.light_proj * vec4<f32>(v.position, 1.0);
}

struct RasLightOut {
    @builtin(position) clip: vec4<f32>,
    // The share of one fiber a fragment stands for: the fiber's width over the ribbon's.
    @location(0) share: f32,
}

// The fiber as a light-facing ribbon at least 1.5 texels wide (so that a thin fiber is never
// missed between texel centres), each fragment carrying the fiber's width over the ribbon's.
@vertex
fn ras_fiber_light(@builtin(vertex_index) v: u32, seg: RasSegment) -> RasLightOut {
    let k = ras_corner(v);
    let p = mix(seg.a.xyz, seg.b.xyz, k.x);
    let r = mix(seg.a.w, seg.b.w, k.x);
    let half_width = max(r, 0.75 * ras.sky.w);
    let across = ras_across(seg.b.xyz - seg.a.xyz, ras.light_axis.xyz);
    var out: RasLightOut;
    out.clip = ras.light_proj * vec4<f32>(p + across * (half_width * k.y), 1.0);
    out.share = r / half_width;
    return out;
}

// Pass 3: the fragment's share of a fiber into its layer; fibers behind the first surface
// (the skin) are left out, so the layers count only fibers a light ray meets before it.
@fragment
fn ras_dom_layers(in: RasLightOut) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(in.clip.xy);
    let surface = textureLoad(ras_shadow, texel, 0);
    if (in.clip.z > surface) {
        discard;
    }
    let behind = (in.clip.z - textureLoad(ras_first, texel, 0)) * ras.light_axis.w;
    let ends = ras.dom.xyz;
    var out = vec4<f32>(0.0);
    if (behind < ends.x) {
        out.x = in.share;
    } else if (behind < ends.y) {
        out.y = in.share;
    } else if (behind < ends.z) {
        out.z = in.share;
    } else {
        out.w = in.share;
    }
    return out;
}

// ---- Reading the maps ----

struct RasLight {
    // 1 if no surface lies between the point and the light, else 0.
    lit: f32,
    // Fibers between the point and the light (the deep opacity map at the point's depth).
    above: f32,
    // Every fiber the map holds along the light ray (in front of the first surface).
    total: f32,
    // Where the point lies within its layer (0 at the front, 1 at the back).
    within: f32,
}

// Fibers in front of a point `behind` world units past the texel's first fiber: whole layers
// in front of it plus the layer it lies in, linearly over the layer's depth (Yuksel and
// Keyser 2008); the open last layer is taken as deep as the one before it.
fn ras_layered(counts: vec4<f32>, behind: f32) -> vec2<f32> {
    let e = ras.dom.xyz;
    let starts = vec4<f32>(0.0, e.x, e.y, e.z);
    let depths = vec4<f32>(e.x, e.y - e.x, e.z - e.y, e.z - e.y);
    let f = clamp((vec4<f32>(behind) - starts) / depths, vec4<f32>(0.0), vec4<f32>(1.0));
    // The fraction within the point's own layer: the last one below 1 (1 past the last).
    let partial = select(vec4<f32>(0.0), f, f < vec4<f32>(1.0));
    let within = select(max(max(partial.x, partial.y), max(partial.z, partial.w)), 1.0, f.w >= 1.0);
    return vec2<f32>(dot(counts, f), within);
}

// The key light at world point `p`, `bias` world units toward the light for the fiber count.
fn ras_light_at(p: vec3<f32>, bias: f32) -> RasLight {
    var out = RasLight(1.0, 0.0, 0.0, 0.0);
    let c = ras.light_proj * vec4<f32>(p, 1.0);
    let uv = vec2<f32>(0.5 * c.x + 0.5, 0.5 - 0.5 * c.y);
    if (any(uv < vec2<f32>(0.0)) || any(uv >= vec2<f32>(1.0)) || c.z < 0.0) {
        // Outside the map: nothing between the point and the light.
        return out;
    }
    let texel = vec2<i32>(uv * ras.key.w);
    let surface = textureLoad(ras_shadow, texel, 0);
    if (c.z - ras.dual.z / ras.light_axis.w > surface) {
        out.lit = 0.0;
    }
    let counts = textureLoad(ras_layers, texel, 0);
    out.total = dot(counts, vec4<f32>(1.0));
    let behind = (c.z - textureLoad(ras_first, texel, 0)) * ras.light_axis.w - bias;
    let layered = ras_layered(counts, behind);
    out.above = layered.x;
    out.within = layered.y;
    return out;
}

// Radiance of a Lambertian surface point: the key light through the fibers in front of it
// (all the map holds: the layers end at the first surface) with the fraction of light rays
// through the texel that find it clear, exp(-n) for the texel's mean count n (fibers placed
// independently), and the sky over the hemisphere above the normal.
fn ras_surface_radiance(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    let l = ras_light_at(p, 0.0);
    let cos_key = max(dot(n, ras.light_axis.xyz), 0.0);
    let key = ras.key.rgb * (cos_key * l.lit * exp(-l.total));
    let sky = FUR_PI * ras.sky.rgb * (0.5 + 0.5 * n.y);
    return albedo / FUR_PI * (key + sky);
}

// ---- Pass 4: the camera ----

struct RasSurfaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) albedo: vec3<f32>,
}

@vertex
fn ras_surface_camera(v: RasVertex) -> RasSurfaceOut {
    var out: RasSurfaceOut;
    out.clip = ras.view_proj * vec4<f32>(v.position, 1.0);
    out.world = v.position;
    out.normal = v.normal;
    out.albedo = v.albedo;
    return out;
}

@fragment
fn ras_surface_shade(in: RasSurfaceOut) -> @location(0) vec4<f32> {
    return vec4<f32>(ras_surface_radiance(in.world, normalize(in.normal), in.albedo), 0.0);
}

struct RasFiberOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) tangent: vec3<f32>,
    @location(2) colour: vec3<f32>,
    @location(3) skin: vec3<f32>,
    @location(4) radius: f32,
    // The coat above the point: fibers along the skin normal, and across its tangent plane.
    @location(5) coat: vec2<f32>,
    // The whole coat's count along the skin normal at the strand's root.
    @location(6) root: f32,
}

// The fiber as a camera-facing ribbon of its own width (the MSAA samples give thin fibers
// their coverage).
@vertex
fn ras_fiber_camera(@builtin(vertex_index) v: u32, seg: RasSegment) -> RasFiberOut {
    let k = ras_corner(v);
    let p = mix(seg.a.xyz, seg.b.xyz, k.x);
    let r = mix(seg.a.w, seg.b.w, k.x);
    let t = seg.b.xyz - seg.a.xyz;
    let across = ras_across(t, ras.eye.xyz - p);
    let world = p + across * (r * k.y);
    var out: RasFiberOut;
    out.clip = ras.view_proj * vec4<f32>(world, 1.0);
    out.world = world;
    out.tangent = t;
    out.colour = seg.colour.rgb;
    out.skin = seg.skin.xyz;
    out.radius = r;
    out.coat = mix(seg.coat.xy, seg.coat.zw, k.x);
    out.root = seg.skin.w;
    return out;
}

// The fiber's directional albedo at theta_r (linear between the table's centred nodes).
fn ras_albedo_at(sin_theta_r: f32) -> vec3<f32> {
    let n = arrayLength(&ras_albedo);
    let theta_r = asin(clamp(sin_theta_r, -1.0, 1.0));
    let x = clamp((theta_r + FUR_HALF_PI) / FUR_PI * f32(n) - 0.5, 0.0, f32(n - 1u));
    let i = min(u32(x), n - 2u);
    return mix(ras_albedo[i].rgb, ras_albedo[i + 1u].rgb, x - f32(i));
}

// 8-point Gauss-Legendre on [0, 1]: nodes and weights.
const RAS_GL_X = array<f32, 8>(0.019855072, 0.101666761, 0.237233795, 0.408282679, 0.591717321, 0.762766205, 0.898333239, 0.980144928);
const RAS_GL_W = array<f32, 8>(0.050614268, 0.111190517, 0.156853323, 0.181341892, 0.181341892, 0.156853323, 0.111190517, 0.050614268);

// The coat's diffuse transmittance from outside down to a point under `above` fibers along
// the skin normal and `across` along its tangent plane (docs/model.md §13, "Indirect
// light"): the mean, over the directions of the half sphere that faces away from the skin
// (uniform in the cosine c to the normal, i.e. in solid angle), of the downward flux mu^k
// after the k fibers on the way, k = above / c as in a flat coat, at most `across` (a curved
// coat ends sooner); per channel, from log2 mu.
fn ras_coat_transmittance(log2_mu: vec3<f32>, above: f32, across: f32) -> vec3<f32> {
    var tau = vec3<f32>(0.0);
    for (var i = 0u; i < 8u; i = i + 1u) {
        let k = min(above / RAS_GL_X[i], max(across, 0.0));
        tau = tau + RAS_GL_W[i] * fur_dual_power(log2_mu, k);
    }
    return tau;
}

// The fur fragment: the key light as S V + D (the shared shader's fur_eval_far_dirs and
// fur_eval_dual_dirs, n and m from the deep opacity map) times cos theta_i and the
// irradiance; the sky and the floor as the fiber's albedo under half the sphere of directions
// lit by them through the coat above and the other half by what the coat below sends back
// (docs/model.md §13, "Indirect light").
@fragment
fn ras_fiber_shade(in: RasFiberOut) -> @location(0) vec4<f32> {
    let t = normalize(in.tangent);
    let wr = normalize(ras.eye.xyz - in.world);
    let wi = ras.light_axis.xyz;
    var l = ras_light_at(in.world, ras.dom.w * in.radius);
    // The fragment's own fiber is in the map too, as the share of a texel it covers
    // (min(1, 2r/texel)), spread over its layer: the layered count holds `within` of it,
    // which belongs to neither n nor m.
    let own = min(1.0, 2.0 * in.radius / ras.sky.w);
    let counted = l.above;
    l.above = max(counted - own * l.within, 0.0);
    let below = max(l.total - counted - own * (1.0 - l.within), 0.0);
    if (ras.dual.w > 0.5) {
        // n, or -1 where a surface shadows the fragment from the key light.
        return vec4<f32>(select(-1.0, l.above, l.lit > 0.0), below, l.total, 1.0);
    }
    // The coat's decay mu and rho^2 at the fragment's colour and theta_r (the colour located
    // on the dual tables' absorption axis; fur_eval_dual_dirs locates it again, the same).
    fur_dual_at = fur_dual_locate(in.colour);
    let sin_theta_r = clamp(dot(wr, t), -1.0, 1.0);
    let here = fur_dual_theta(asin(sin_theta_r));
    let log2_mu = fur_dual_field(here, FUR_DUAL_LOG2_DECAY);
    let rho2 = fur_dual_coat(here);
    var rgb = vec3<f32>(0.0);
    // The key's light on the skin under the coat (a Lambertian skin under the whole line's
    // fibers, the layer stack's flux through them over the skin, T_n).
    var skin = vec3<f32>(0.0);
    if (l.lit > 0.0) {
        let s = fur_eval_far_dirs(wi, wr, t, in.colour);
        // The coat below as the light scattered inside the coat sees it (the count along the
        // key's line rescaled by the key's incidence on the skin under the strand), and the
        // light scattered through the fibers above as the diffuse flux the coat takes in
        // per unit of its area (d_f rescaled by the same incidence).
        let cos_skin = dot(wi, normalize(in.skin));
        let m = fur_dual_below_at_incidence(below, cos_skin);
        let d_f = fur_dual_forward_density_at_incidence(ras.dual.x, cos_skin);
        let d = fur_eval_dual_dirs(wi, wr, t, l.above, m, d_f, ras.dual.y, in.colour);
        let ct = dot(wi, t);
        let cos_i = sqrt(max(1.0 - ct * ct, 0.0));
        rgb = ras.key.rgb * (s.total * clamp(1.0 - l.above, 0.0, 1.0) + d) * cos_i;
        let t_n = fur_downward_flux(fur_dual_power(log2_mu, l.total), vec3<f32>(1.0), rho2);
        skin = ras.skin_albedo.rgb / FUR_PI * ras.key.rgb * (max(cos_skin, 0.0) * t_n);
    }
    // The light from below: the floor's radiance under the fragment (the sky past its edge).
    var under = ras.sky.rgb;
    let f = ras.floor_at;
    let foot = vec3<f32>(in.world.x, f.y, in.world.z);
    if (f.w > 0.0 && all(abs(foot.xz - f.xz) <= vec2<f32>(ras.floor_albedo.w))) {
        under = ras_surface_radiance(foot, vec3<f32>(0.0, 1.0, 0.0), ras.floor_albedo.rgb);
    }
    let up = normalize(in.skin).y;
    let around = ras.sky.rgb * (0.5 + 0.5 * up) + under * (0.5 - 0.5 * up);
    // The half facing away from the skin: `around` through the coat above (tau). The half
    // facing the skin: what the coat below sends back up, as a semi-infinite coat does
    // (R_inf = sqrt(rho^2) of `around` through the coat above), and the skin's key light
    // through the coat below (the root's count less the count above). Both at the fragment's
    // colour and theta_r.
    let above = max(in.coat.x, 0.0);
    let tau = ras_coat_transmittance(log2_mu, above, in.coat.y);
    let tau_below = ras_coat_transmittance(log2_mu, max(in.root - above, 0.0), in.coat.y);
    let r_inf = sqrt(max(rho2, vec3<f32>(0.0)));
    let incident = around * tau * (1.0 + r_inf) + skin * tau_below;
    rgb = rgb + 0.5 * ras_albedo_at(sin_theta_r) * incident;
    return vec4<f32>(rgb, 1.0);
}
