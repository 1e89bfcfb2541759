#version 330 core
// Classic Phong as a GLSL 3.30 fragment shader with its own uniform names,
// written for xval's docs (docs/shaders.md); phong330.json maps each name
// to a scene quantity. F = C * (ka A + kd D) + ks S, D = max(N.L, 0),
// S = max(R.V, 0)^n, one point light.
uniform vec3 u_light_pos;
uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform float u_ka;
uniform float u_kd;
uniform float u_ks;
uniform float u_exponent;
uniform sampler2D u_albedo;
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
out vec4 frag_colour;

void main() {
  vec3 n = normalize(v_normal);
  vec3 l = normalize(u_light_pos - v_position);
  vec3 v = normalize(u_eye - v_position);
  vec3 r = 2.0 * dot(n, l) * n - l;
  float d = max(dot(n, l), 0.0);
  float s = pow(max(dot(r, v), 0.0), u_exponent);
  vec3 c = texture(u_albedo, v_uv).rgb;
  frag_colour = vec4(c * (u_ka * u_ambient + u_kd * d) + u_ks * s, 1.0);
}
