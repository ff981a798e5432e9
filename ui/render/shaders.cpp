// GLSL sources of the 3D view's three programs, without their version line (GlProgram puts
// gl.hpp's glsl_prologue first: GLSL 3.30 on the desktop, GLSL ES 3.00 in the browser).
#include "ui/render/shaders.hpp"

namespace isoparm::ui::shaders {

const char* const mesh_vs = R"(
in vec3 a_position;
in vec3 a_second; // normal
in float a_scalar; // the analysis value (a curvature), 1e30 where undefined
uniform mat4 u_view_proj;
uniform mat4 u_view;
out vec3 v_eye_pos;
out vec3 v_eye_normal;
out float v_scalar;
void main() {
    v_scalar = a_scalar;
    vec4 eye = u_view * vec4(a_position, 1.0);
    v_eye_pos = eye.xyz;
    v_eye_normal = mat3(u_view) * a_second;
    gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

const char* const mesh_fs = R"(
in vec3 v_eye_pos;
in vec3 v_eye_normal;
in float v_scalar;
uniform vec4 u_color;
// 0 off; 1 to 4 a curvature (K, H, k_max, k_min); 5 zebra; 6 isophotes. A constant: one program
// each for off, the curvatures, zebra and isophotes (renderer.cpp), only its own branch compiled.
const int analysis = ISOPARM_ANALYSIS;
uniform vec2 u_range;     // the colour bar's [low, high]
uniform int u_diverging;  // 1: blue - white - red about zero
uniform float u_stripes;
uniform vec2 u_zebra_dir; // the zebra stripes' direction on screen
out vec4 frag;
// Moreland's cool-warm diverging map (blue, light grey, red) and a three-stop sequential one
// (dark purple, teal, yellow): the colour bar in the view draws the same (ui/view/analysis).
vec3 diverging(float t) { // t in [-1, 1]
    vec3 cool = vec3(0.23, 0.30, 0.75), mid = vec3(0.87, 0.87, 0.87), warm = vec3(0.71, 0.02, 0.15);
    return t < 0.0 ? mix(mid, cool, -t) : mix(mid, warm, t);
}
vec3 sequential(float t) { // t in [0, 1]
    vec3 a = vec3(0.27, 0.00, 0.33), b = vec3(0.13, 0.57, 0.55), c = vec3(0.99, 0.91, 0.14);
    return t < 0.5 ? mix(a, b, t * 2.0) : mix(b, c, t * 2.0 - 1.0);
}
// Blinn-Phong (Blinn 1977) with a key and a fill light in eye space; the back side is lit
// with the flipped normal and slightly darker, so students can tell the two sides apart.
void main() {
    vec3 n = normalize(v_eye_normal);
    float side = 1.0;
    if (!gl_FrontFacing) { n = -n; side = 0.82; }
    vec3 view_dir = normalize(-v_eye_pos);
    vec3 key = normalize(vec3(-0.35, 0.55, 0.75));
    vec3 fill = normalize(vec3(0.6, -0.3, 0.45));
    float diffuse = max(dot(n, key), 0.0) * 0.68 + max(dot(n, fill), 0.0) * 0.22;
    float spec = pow(max(dot(n, normalize(key + view_dir)), 0.0), 48.0) * 0.32;
    vec3 base = u_color.rgb;
    float light = 0.24 + diffuse;
    if (analysis >= 1 && analysis <= 4) {
        if (abs(v_scalar) > 1e20) {
            // Undefined (a pole, a zero denominator): hatched, never a made-up colour.
            float h = mod(floor((gl_FragCoord.x + gl_FragCoord.y) / 6.0), 2.0);
            base = mix(vec3(0.35), vec3(0.55), h);
        } else if (u_diverging == 1) {
            float m = max(abs(u_range.x), abs(u_range.y));
            base = diverging(clamp(m > 0.0 ? v_scalar / m : 0.0, -1.0, 1.0));
        } else {
            float w = u_range.y - u_range.x;
            base = sequential(clamp(w > 0.0 ? (v_scalar - u_range.x) / w : 0.5, 0.0, 1.0));
        }
        light = 0.55 + 0.5 * diffuse; // the colour carries the value: lighting only hints shape
        spec *= 0.3;
    } else if (analysis == 5) {
        // Zebra: stripes of the reflected view direction (a striped environment), so a
        // curvature jump kinks them and a tangent jump breaks them.
        vec3 r = reflect(-view_dir, n);
        float s = fract(asin(clamp(dot(r.xy, u_zebra_dir), -1.0, 1.0)) / 3.14159265 * u_stripes);
        base = vec3(s < 0.5 ? 0.06 : 0.94);
        light = 1.0;
        spec = 0.0;
    } else if (analysis == 6) {
        // Isophotes: curves of equal angle between the normal and the key light.
        float a = acos(clamp(dot(n, key), -1.0, 1.0)) / 3.14159265 * u_stripes;
        base = fract(a) < 0.5 ? base : base * 0.35;
    }
    vec3 rgb = base * light * side + vec3(spec);
    frag = vec4(rgb, u_color.a);
}
)";

// A segment per instance: its two ends (and colours) are per-instance attributes and
// gl_VertexID picks the quad's corner, 0 and 1 at the start, 2 and 3 at the end (a triangle
// strip). This is what a geometry shader would emit, built where WebGL 2 can build it.
const char* const line_vs = R"(
in vec3 a_position; // the segment's start
in vec4 a_second;   // its colour
in vec3 a_end;      // the segment's end
in vec4 a_end_color;
uniform mat4 u_view_proj;
uniform vec2 u_viewport; // pixels
uniform float u_width;   // pixels
uniform float u_depth_bias;
out vec4 f_color;
out float f_edge; // signed distance from the centre line, pixels
void main() {
    vec4 p0 = u_view_proj * vec4(a_position, 1.0), p1 = u_view_proj * vec4(a_end, 1.0);
    vec4 c0 = a_second, c1 = a_end_color;
    // Clip against the near plane (w = eps) before dividing: otherwise a segment passing
    // behind the eye would flip across the screen.
    const float eps = 1e-5;
    if (p0.w < eps && p1.w < eps) { // wholly behind the eye: a point outside the clip volume
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        f_color = vec4(0.0);
        f_edge = 0.0;
        return;
    }
    if (p0.w < eps) { float t = (eps - p0.w) / (p1.w - p0.w); p0 = mix(p0, p1, t); c0 = mix(c0, c1, t); }
    if (p1.w < eps) { float t = (eps - p1.w) / (p0.w - p1.w); p1 = mix(p1, p0, t); c1 = mix(c1, c0, t); }
    vec2 s0 = p0.xy / p0.w * u_viewport * 0.5;
    vec2 s1 = p1.xy / p1.w * u_viewport * 0.5;
    vec2 d = s1 - s0;
    float len = length(d);
    d = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    // One extra pixel each side for the antialiased edge the fragment shader fades out.
    float half_total = u_width * 0.5 + 1.0;
    vec2 n = vec2(-d.y, d.x) * half_total;
    vec2 e = d * (u_width * 0.5); // half-width caps close the joints of polylines
    vec2 to_ndc = 2.0 / u_viewport;
    bool start = gl_VertexID < 2;
    float side = (gl_VertexID & 1) == 0 ? -1.0 : 1.0;
    vec4 p = start ? p0 : p1;
    vec2 s = start ? s0 - e : s1 + e;
    gl_Position = vec4((s + side * n) * to_ndc * p.w, p.z - u_depth_bias * p.w, p.w);
    f_color = start ? c0 : c1;
    f_edge = side * half_total;
}
)";

// The overlay's depth test in one pass where the scene's depth is a texture (no multisampling:
// RenderTarget::depth_texture): a fragment behind the scene's depth there is drawn at
// u_hidden_alpha (u_depth_mode 1) or dropped (2), as the GL_GREATER pass and the GL_LEQUAL
// pass would draw it; 0: the depth test decides (or nothing does).
#define ISOPARM_OVERLAY_DEPTH                                                                      \
    "uniform highp sampler2D u_scene_depth;\n"                                                     \
    "uniform int u_depth_mode;\n"                                                                  \
    "uniform float u_hidden_alpha;\n"                                                              \
    "float overlay_alpha(float visible_alpha) {\n"                                                 \
    "    if (u_depth_mode == 0) return visible_alpha;\n"                                           \
    "    float scene = texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy), 0).r;\n"                  \
    "    if (gl_FragCoord.z <= scene) return visible_alpha;\n"                                     \
    "    if (u_depth_mode == 2) discard;\n"                                                        \
    "    return u_hidden_alpha;\n"                                                                 \
    "}\n"

const char* const line_fs = ISOPARM_OVERLAY_DEPTH R"(
in vec4 f_color;
in float f_edge;
uniform float u_alpha;
uniform float u_width;
out vec4 frag;
// Coverage falls from 1 to 0 over the pixel outside the line's width: antialiasing that
// needs no multisampling.
void main() {
    float coverage = clamp(u_width * 0.5 + 0.5 - abs(f_edge), 0.0, 1.0);
    frag = vec4(f_color.rgb, f_color.a * overlay_alpha(u_alpha) * coverage);
}
)";

// A point per instance; gl_VertexID picks the corner of its square (a triangle strip).
const char* const point_vs = R"(
in vec3 a_position;
in vec4 a_second; // colour
uniform mat4 u_view_proj;
uniform vec2 u_viewport;
uniform float u_size; // diameter in pixels
out vec4 f_color;
out vec2 f_local;
void main() {
    vec4 p = u_view_proj * vec4(a_position, 1.0);
    f_color = a_second;
    if (p.w <= 1e-5) { // behind the eye: outside the clip volume
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        f_local = vec2(0.0);
        return;
    }
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
    vec2 r = vec2(u_size * 0.5 + 1.0) * 2.0 / u_viewport * p.w;
    float k = (u_size * 0.5 + 1.0) / (u_size * 0.5); // one pixel of room for the soft edge
    f_local = corner * k;
    gl_Position = vec4(p.xy + corner * r, p.z, p.w);
}
)";

const char* const point_fs = ISOPARM_OVERLAY_DEPTH R"(
in vec4 f_color;
in vec2 f_local; // [-1, 1] is the disk's radius
uniform float u_size;
uniform int u_sphere;
uniform float u_alpha;
out vec4 frag;
void main() {
    float r = length(f_local);
    float px = 2.0 / u_size; // one pixel in local units
    float coverage = clamp((1.0 - r) / px + 0.5, 0.0, 1.0);
    if (coverage <= 0.0) discard;
    vec3 rgb;
    if (u_sphere == 1) {
        // An impostor sphere lit like the surfaces.
        vec3 n = vec3(f_local.x, f_local.y, sqrt(max(1.0 - r * r, 0.0)));
        vec3 key = normalize(vec3(-0.35, 0.55, 0.75));
        float d = max(dot(n, key), 0.0);
        float s = pow(max(dot(n, normalize(key + vec3(0, 0, 1))), 0.0), 40.0);
        rgb = f_color.rgb * (0.3 + 0.75 * d) + vec3(0.45 * s);
    } else {
        // A flat disk with a dark rim that keeps it visible on any background.
        float rim = smoothstep(1.0 - 2.5 * px, 1.0 - 1.5 * px, r);
        rgb = mix(f_color.rgb, f_color.rgb * 0.25, rim);
    }
    frag = vec4(rgb, f_color.a * coverage * overlay_alpha(u_alpha));
}
)";

} // namespace isoparm::ui::shaders
