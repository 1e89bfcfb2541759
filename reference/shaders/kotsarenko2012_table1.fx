float4x4 WorldInverseTranspose : WorldInverseTranspose < 
string UIWidget="None"; >; 
float4x4 WorldViewProjection : WorldViewProjection < string 
UIWidget="None"; >; 
float4x4 World : World < string UIWidget="None"; >; 
float3   EyePos : CameraPosition < string UIWidget="None"; >; 
 
float3 LightPos : Position < 
  string UIName =  "Lamp 0 Position"; 
  string Object = "PointLight0"; 
  string Space  = "World"; > = {-0.5f, 2.0f, 1.25f}; 
 
float AmbientValue < 
  string UIName   =  "Ambient Value"; 
  string UIWidget = "slider"; 
  float UIMin  = 0.0; 
  float UIMax  = 1.0; 
  float UIStep = 0.1; > = 0.1; 
 
float SpecularPower : SpecularPower < 
  string UIWidget = "slider"; 
  float UIMin = 0.0; 
  float UIMax = 16.0; 
  float UIStep = 1.0; 
  string UIName =  "Specular Power"; > = 55.0; 
 
texture ColorTexture : DIFFUSE < 
  string ResourceName = "default_color.dds"; 
  string UIName       =  "Diffuse Texture"; 
  string ResourceType = "2D"; >; 
 
sampler2D ColorSampler = sampler_state { 
  Texture  = <ColorTexture>; 
  FILTER   = MIN_MAG_MIP_LINEAR; 
  AddressU = Wrap; 
  AddressV = Wrap; }; 
 
struct OutputPhongVS { 
  float4 Pos   : POSITION; 
  float2 TexAt : TEXCOORD0; 
 
float3 NormalWorld: TEXCOORD1; 
  float3 PosWorld   : TEXCOORD2; }; 
 
OutputPhongVS PhongVertexShader( 
 float3 InPos   : POSITION, 
 float2 InpTex  : TEXCOORD0, 
 float3 InNormal: NORMAL) { 
  OutputPhongVS OutVS = (OutputPhongVS)0; 
 
  OutVS.NormalWorld = mul(float4(InNormal, 0.0f), 
   WorldInverseTranspose).xyz; 
  OutVS.NormalWorld = normalize(OutVS.NormalWorld); 
 
  OutVS.PosWorld = mul(float4(InPos, 1.0f), World).xyz; 
  OutVS.Pos = mul(float4(InPos, 1.0f), WorldViewProjection); 
  OutVS.TexAt = InpTex; 
 
  return OutVS; } 
 
float3 RGBtoYIQ(float3 InCol) { 
  float3 OutCol; 
 
 

  OutCol.y = 0.29889531f * InCol.r + 0.58662247f * InCol.g + 
0.11448223f * InCol.b; 
  OutCol.x = 0.59597799f * InCol.r + -0.27417610f * InCol.g + -
0.32180189f * InCol.b; 
  OutCol.z = 0.21147017f * InCol.r + -0.52261711f * InCol.g + 
0.31114694f * InCol.b; 
  return OutCol; } 
 
float3 YIQtoRGB(float3 InCol) { 
  float3 OutCol; 
 
  OutCol.r = InCol.y + 0.95608445f * InCol.x + 0.62088850f * 
InCol.z; 
  OutCol.g = InCol.y - 0.27137664f * InCol.x - 0.64860590f * 
InCol.z; 
  OutCol.b = InCol.y - 1.10561724f * InCol.x + 1.70250126f * 
InCol.z; 
 
  return saturate(OutCol); } 
 
float4 LumaPhongDiffuse(float3 NormalWorld, float3 PosWorld, 
float2 TexAt) { 
  float3 ToEye = normalize(EyePos - PosWorld); 
 
float3 LightVector = normalize(LightPos - PosWorld); 
float3 LightVector = normalize(LightPos - PosWorld); 
 
float3 Reflection = normalize(2.0f * NormalWorld * 
dot(NormalWorld, 
    LightVector) - LightVector); 
 
  float Diffuse = saturate(saturate(dot(LightVector, 
NormalWorld)) + 
    AmbientValue); 
 
  float Specular = pow(saturate(dot(Reflection, ToEye)), 
SpecularPower); 
 
  float3 TexCol = tex2D(ColorSampler, TexAt).rgb; 
 
  float3 WorkCol = RGBtoYIQ(TexCol); 
 
  WorkCol.y = WorkCol.y * Diffuse + Specular * 1.0 - 0.1; 
 
  TexCol = YIQtoRGB(WorkCol); 
 
  return float4(TexCol, 1.0); } 
 
float4 LumaDiffusePS(OutputPhongVS InPS) : COLOR { 
  return LumaPhongDiffuse(InPS.NormalWorld, InPS.PosWorld, 
InPS.TexAt); } 
 
technique PhongDiffuse < string Script = "Pass=p0;"; > { 
  pass p0 < string Script = "Draw=geometry;"; > { 
    VertexShader = compile vs_2_0 PhongVertexShader(); 
 
ZEnable = true; 
    ZWriteEnable = true; 
    ZFunc = LessEqual; 
    AlphaBlendEnable = false; 
    CullMode = None; 
    PixelShader = compile ps_2_0 LumaDiffusePS();  } 
