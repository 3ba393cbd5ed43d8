// The live error view (show error): the current mode's frame against the exact mode's, pixel by
// pixel. The exact frame's alpha is 0 on the pixels its mirrors and glass drew (the reflectors).
//  u_output 0 (to the screen): over the reflectors a heat map of the largest channel difference
//    (dark blue at 0 levels, through green to yellow at 32, orange to red past it, red at 96 and
//    more); elsewhere the current frame, grey and dimmed;
//  u_output 1 (read back and summed, core/error_view_stats.h): the absolute differences in RGB, and
//    alpha 1 on a reflector pixel, 0 elsewhere.
uniform highp sampler2D u_current;
uniform highp sampler2D u_exact;
uniform int u_output;

out vec4 fragColour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(u_current, p, 0);
  vec4 b = texelFetch(u_exact, p, 0);
  bool reflector = b.a < 0.5;
  vec3 diff = abs(floor(a.rgb * 255.0 + 0.5) - floor(b.rgb * 255.0 + 0.5));
  float worst = max(diff.r, max(diff.g, diff.b));
  if (u_output == 1) {
    fragColour = reflector ? vec4(diff / 255.0, 1.0) : vec4(0.0);
    return;
  }
  if (!reflector) {
    fragColour = vec4(vec3(dot(a.rgb, vec3(0.299, 0.587, 0.114)) * 0.55), 1.0);
    return;
  }
  vec3 heat;
  if (worst <= 32.0) {
    float t = worst / 32.0;
    heat = t < 0.5 ? mix(vec3(0.05, 0.08, 0.35), vec3(0.1, 0.8, 0.3), t * 2.0)
                   : mix(vec3(0.1, 0.8, 0.3), vec3(1.0, 0.95, 0.1), t * 2.0 - 1.0);
  } else {
    heat = mix(vec3(1.0, 0.55, 0.0), vec3(1.0, 0.0, 0.0), clamp((worst - 32.0) / 64.0, 0.0, 1.0));
  }
  fragColour = vec4(heat, 1.0);
}
