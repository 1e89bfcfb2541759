// Classic Phong in the style of an NVIDIA FX Composer effect, written for
// xval's docs (docs/shaders.md): F = C * (ka A + kd D) + ks S with
// D = saturate(N.L), S = saturate(R.V)^n, one point light.
// Unlike the paper's listing it re-normalises the interpolated normal in the
// pixel shader, as the reference scenes ask (normalize_normal: true).

float4x4 WorldITXf : WorldInverseTranspose < string UIWidget = "None"; >;
float4x4 WvpXf : WorldViewProjection < string UIWidget = "None"; >;
float4x4 WorldXf : World < string UIWidget = "None"; >;
float3 EyePosition : CameraPosition < string UIWidget = "None"; >;

float3 Lamp0Pos : Position <
  string Object = "PointLight0";
  string UIName = "Lamp 0 Position";
  string Space = "World"; > = {-0.5f, 2.0f, 1.25f};

float3 AmbientColor < string UIName = "Ambient"; > = {0.1f, 0.1f, 0.1f};
float Ka < string UIName = "Ambient strength"; > = 1.0;
float Kd < string UIName = "Diffuse strength"; > = 1.0;
float Ks < string UIName = "Specular strength"; > = 1.0;
float SpecExpon : SpecularPower < string UIName = "Specular Power"; > = 55.0;

texture ColorTexture : DIFFUSE <
  string ResourceName = "default_color.dds";
  string ResourceType = "2D"; >;

sampler2D ColorSampler = sampler_state {
  Texture = <ColorTexture>;
  MinFilter = Linear;
  MagFilter = Linear;
  MipFilter = None;
  AddressU = Wrap;
  AddressV = Wrap; };

struct AppData {
  float3 Position : POSITION;
  float2 UV : TEXCOORD0;
  float3 Normal : NORMAL;
};

struct VertexOutput {
  float4 HPosition : POSITION;
  float2 UV : TEXCOORD0;
  float3 WorldNormal : TEXCOORD1;
  float3 WorldPos : TEXCOORD2;
};

VertexOutput PhongVS(AppData IN) {
  VertexOutput OUT = (VertexOutput)0;
  OUT.WorldNormal = mul(float4(IN.Normal, 0.0f), WorldITXf).xyz;
  OUT.WorldPos = mul(float4(IN.Position, 1.0f), WorldXf).xyz;
  OUT.HPosition = mul(float4(IN.Position, 1.0f), WvpXf);
  OUT.UV = IN.UV;
  return OUT;
}

float4 PhongPS(VertexOutput IN) : COLOR {
  float3 N = normalize(IN.WorldNormal);
  float3 L = normalize(Lamp0Pos - IN.WorldPos);
  float3 V = normalize(EyePosition - IN.WorldPos);
  float3 R = 2.0f * dot(N, L) * N - L;
  float D = saturate(dot(N, L));
  float S = pow(saturate(dot(R, V)), SpecExpon);
  float3 C = tex2D(ColorSampler, IN.UV).rgb;
  return float4(C * (Ka * AmbientColor + Kd * D) + Ks * S, 1.0f);
}

technique Main < string Script = "Pass=p0;"; > {
  pass p0 < string Script = "Draw=geometry;"; > {
    VertexShader = compile vs_3_0 PhongVS();
    ZEnable = true;
    ZWriteEnable = true;
    ZFunc = LessEqual;
    AlphaBlendEnable = false;
    CullMode = None;
    PixelShader = compile ps_3_0 PhongPS();
  }
}
