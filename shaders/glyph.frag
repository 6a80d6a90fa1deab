// Text: coverage from the font atlas (stb_truetype, oversampled), premultiplied colour.
in vec2 vLocal;  // atlas texture coordinates
in vec4 vColor;
uniform sampler2D uGlyphs;
out vec4 fragColor;

void main() {
  float c = texture(uGlyphs, vLocal).r;
  float alpha = vColor.a * (uAntialias > 0.5 ? c : step(0.5, c));
  fragColor = vec4(vColor.rgb * alpha, alpha);
}
