// Tone curves for the GPU: a line-by-line mirror of src/core/ToneCurves.cpp and ToneCurvesAces.cpp (same
// constants, same order of operations, float). Change both together; the GL mirror test holds them within 1/255
// after sRGB encoding.
// No #version: this file is included after the pipeline's #version line. Core GLSL 4.50 only.
//
// Contract (as toneMap() in ToneCurves.h): input is exposed scene-linear Rec.709, clamped to [0, 65504];
// output is LINEAR display light in [0, 1], before the sRGB OETF.
//
// Sources (details in ToneCurves.cpp and ToneCurvesAces.cpp): Reinhard et al. 2002; Hable 2010 (Uncharted 2); Lottes GDC 2016;
// Uchimura CEDEC 2017; Narkowicz 2016; Hill, BakingLab ACES.hlsl; ACES 1.x CTL (ampas/aces-dev: RRT.ctl,
// ACESlib.RRT_Common.ctl, ACESlib.Tonescales.ctl, ACESlib.ODT_Common.ctl, ODT.Academy.sRGB_100nits_dim.ctl);
// Sobotka's AgX in Wrensch's minimal form (iolite-engine.com/blog_posts/minimal_agx_implementation);
// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md).
#ifndef PHOTOPIC_TONECURVES_H_GLSL
#define PHOTOPIC_TONECURVES_H_GLSL

// Modes: static_cast<int>(photopic::ToneMapper).
#define TONEMAP_LINEAR 0
#define TONEMAP_REINHARD 1
#define TONEMAP_REINHARD_EXTENDED 2
#define TONEMAP_HABLE 3
#define TONEMAP_LOTTES 4
#define TONEMAP_UCHIMURA 5
#define TONEMAP_ACES_NARKOWICZ 6
#define TONEMAP_ACES_FITTED 7
#define TONEMAP_ACES 8
#define TONEMAP_AGX 9
#define TONEMAP_NEUTRAL 10

// Looks: static_cast<int>(photopic::AgxLook).
#define AGX_LOOK_BASE 0
#define AGX_LOOK_PUNCHY 1
#define AGX_LOOK_GOLDEN 2

const float kTmHalfMax = 65504.0; // largest finite half float: the HDR target's range

// -------------------------------------------------------------------------------- Reinhard
vec3 tmReinhard(vec3 x) {
    return x / (1.0 + x);
}

vec3 tmReinhardExtended(vec3 x, float whitePoint) {
    float w = max(whitePoint, 1e-4);
    x = min(x, vec3(w));
    return x * (1.0 + x / (w * w)) / (1.0 + x);
}

// -------------------------------------------------------------------------------- Hable
const float kHableA = 0.15;
const float kHableB = 0.50;
const float kHableC = 0.10;
const float kHableD = 0.20;
const float kHableE = 0.02;
const float kHableF = 0.30;
const float kHableW = 11.2;
const float kHableExposureBias = 2.0;

// U(x) over one denominator, free of the published form's cancellation near 0 (see ToneCurves.cpp).
vec3 tmHableU(vec3 x) {
    return x * ((kHableF - kHableE) * kHableA * x + (kHableF * kHableC - kHableE) * kHableB) /
           (kHableF * (x * (kHableA * x + kHableB) + kHableD * kHableF));
}

vec3 tmHable(vec3 x) {
    return tmHableU(kHableExposureBias * x) / tmHableU(vec3(kHableW));
}

// -------------------------------------------------------------------------------- Lottes
const float kLottesA = 1.6;
const float kLottesD = 0.977;
const float kLottesAD = 1.5632;
const float kLottesHdrMax = 8.0;
const float kLottesB = 1.0730397117;
const float kLottesC = 0.1674199382;

vec3 tmLottes(vec3 x) {
    x = min(x, vec3(kLottesHdrMax));
    return pow(x, vec3(kLottesA)) / (pow(x, vec3(kLottesAD)) * kLottesB + kLottesC);
}

// -------------------------------------------------------------------------------- Uchimura
const float kUchimuraP = 1.0;
const float kUchimuraA = 1.0;
const float kUchimuraM = 0.22;
const float kUchimuraL = 0.4;
const float kUchimuraC = 1.33;
const float kUchimuraB = 0.0;

vec3 tmUchimura(vec3 x) {
    float l0 = ((kUchimuraP - kUchimuraM) * kUchimuraL) / kUchimuraA;
    float s0 = kUchimuraM + l0;
    float s1 = kUchimuraM + kUchimuraA * l0;
    float c2 = (kUchimuraA * kUchimuraP) / (kUchimuraP - s1);
    float cp = -c2 / kUchimuraP;

    vec3 w0 = 1.0 - smoothstep(vec3(0.0), vec3(kUchimuraM), x);
    vec3 w2 = step(vec3(kUchimuraM + l0), x);
    vec3 w1 = 1.0 - w0 - w2;

    vec3 t = kUchimuraM * pow(x / kUchimuraM, vec3(kUchimuraC)) + kUchimuraB;
    vec3 s = kUchimuraP - (kUchimuraP - s1) * exp(cp * (x - s0));
    vec3 l = kUchimuraM + kUchimuraA * (x - kUchimuraM);

    return t * w0 + l * w1 + s * w2;
}

// -------------------------------------------------------------------------------- Narkowicz
vec3 tmAcesNarkowicz(vec3 x) {
    return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
}

// -------------------------------------------------------------------------------- Hill fit
const mat3 kHillInput = mat3(0.59719, 0.07600, 0.02840,
                             0.35458, 0.90834, 0.13383,
                             0.04823, 0.01566, 0.83777);
const mat3 kHillOutput = mat3(1.60475, -0.10208, -0.00327,
                              -0.53108, 1.10813, -0.07276,
                              -0.07367, -0.00605, 1.07602);

vec3 tmAcesFitted(vec3 x) {
    vec3 v = kHillInput * x;
    v = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
    return kHillOutput * v;
}

// -------------------------------------------------------------------------------- ACES 1.x
const mat3 kAcesRec709ToAp0 = mat3(0.4396329819, 0.0897764430, 0.0175411704,
                                   0.3829886982, 0.8134394287, 0.1115465533,
                                   0.1773783199, 0.0967841283, 0.8709122763);
const mat3 kAcesAp0ToAp1 = mat3(1.4514393161, -0.0765537734, 0.0083161484,
                                -0.2365107469, 1.1762296998, -0.0060324498,
                                -0.2149285693, -0.0996759264, 0.9977163014);
const mat3 kAcesAp1ToXyz = mat3(0.6624541811, 0.2722287168, -0.0055746495,
                                0.1340042065, 0.6740817658, 0.0040607335,
                                0.1561876870, 0.0536895174, 1.0103391003);
const mat3 kAcesXyzToAp1 = mat3(1.6410233797, -0.6636628587, 0.0117218943,
                                -0.3248032942, 1.6153315917, -0.0082844420,
                                -0.2364246952, 0.0167563477, 0.9883948585);
const mat3 kAcesAp1ToRec709 = mat3(1.7050509927, -0.1302564175, -0.0240033568,
                                   -0.6217921207, 1.1408047366, -0.1289689761,
                                   -0.0832588720, -0.0105483191, 1.1529723329);
const mat3 kAcesRrtSat = mat3(0.9708891487, 0.0108891487, 0.0108891487,
                              0.0269632706, 0.9869632706, 0.0269632706,
                              0.0021475807, 0.0021475807, 0.9621475807);
const mat3 kAcesOdtSat = mat3(0.9490560102, 0.0190560102, 0.0190560102,
                              0.0471857236, 0.9771857236, 0.0471857236,
                              0.0037582662, 0.0037582662, 0.9337582662);

const float kAcesHalfMin = 5.96046448e-08;
const float kAcesLog10Of2 = 0.30102999566;
const float kAcesLog2Of10 = 3.32192809489;

float tmAcesLog10(float x) {
    return log2(x) * kAcesLog10Of2;
}

float tmAcesPow10(float y) {
    return exp2(y * kAcesLog2Of10);
}

const float kAcesGlowGain = 0.05;
const float kAcesGlowMid = 0.08;
const float kAcesRedScale = 0.82;
const float kAcesRedPivot = 0.03;
const float kAcesRedHue = 0.0;
const float kAcesRedWidth = 135.0;

float tmAcesSplineSegment(float c0, float c1, float c2, float t) {
    float a = 0.5 * c0 - c1 + 0.5 * c2;
    float b = -c0 + c1;
    float c = 0.5 * c0 + 0.5 * c1;
    return t * t * a + t * b + c;
}

const float kC5LogMinX = -5.2601774299;
const float kC5LogMidX = -0.7447274949;
const float kC5LogMaxX = 4.6738124271;
const float kC5LogMinY = -4.0;
const float kC5LogMaxY = 4.0;
const float kC5CoefsLow[6] = float[6](-4.0000000000, -4.0000000000, -3.1573765773,
                                      -0.4852499958, 1.8477324706, 1.8477324706);
const float kC5CoefsHigh[6] = float[6](-0.7185482425, 2.0810307172, 3.6681241237,
                                       4.0000000000, 4.0000000000, 4.0000000000);

float tmAcesSplineC5(float x) {
    const int kKnotsLow = 4;
    const int kKnotsHigh = 4;

    float logx = tmAcesLog10(max(x, kAcesHalfMin));
    float logy = 0.0;
    if (logx <= kC5LogMinX) {
        logy = kC5LogMinY;
    } else if (logx < kC5LogMidX) {
        float knot = float(kKnotsLow - 1) * (logx - kC5LogMinX) / (kC5LogMidX - kC5LogMinX);
        int j = min(int(knot), kKnotsLow - 1);
        float t = knot - float(j);
        logy = tmAcesSplineSegment(kC5CoefsLow[j], kC5CoefsLow[j + 1], kC5CoefsLow[j + 2], t);
    } else if (logx < kC5LogMaxX) {
        float knot = float(kKnotsHigh - 1) * (logx - kC5LogMidX) / (kC5LogMaxX - kC5LogMidX);
        int j = min(int(knot), kKnotsHigh - 1);
        float t = knot - float(j);
        logy = tmAcesSplineSegment(kC5CoefsHigh[j], kC5CoefsHigh[j + 1], kC5CoefsHigh[j + 2], t);
    } else {
        logy = kC5LogMaxY;
    }
    return tmAcesPow10(logy);
}

const float kC9LogMinX = -2.5406236189;
const float kC9LogMidX = 0.6812412373;
const float kC9LogMaxX = 3.0024768101;
const float kC9LogMinY = -1.6989700043;
const float kC9LogMaxY = 1.6812412374;
const float kC9SlopeHigh = 0.04;
const float kC9CoefsLow[10] = float[10](-1.6989700043, -1.6989700043, -1.4779000000, -1.2291000000,
                                        -0.8648000000, -0.4480000000, 0.0051800000, 0.4511080334,
                                        0.9113744414, 0.9113744414);
const float kC9CoefsHigh[10] = float[10](0.5154386965, 0.8470437783, 1.1358000000, 1.3802000000,
                                         1.5197000000, 1.5985000000, 1.6467000000, 1.6746091357,
                                         1.6878733390, 1.6878733390);

float tmAcesSplineC9(float x) {
    const int kKnotsLow = 8;
    const int kKnotsHigh = 8;

    float logx = tmAcesLog10(max(x, kAcesHalfMin));
    float logy = 0.0;
    if (logx <= kC9LogMinX) {
        logy = kC9LogMinY;
    } else if (logx < kC9LogMidX) {
        float knot = float(kKnotsLow - 1) * (logx - kC9LogMinX) / (kC9LogMidX - kC9LogMinX);
        int j = min(int(knot), kKnotsLow - 1);
        float t = knot - float(j);
        logy = tmAcesSplineSegment(kC9CoefsLow[j], kC9CoefsLow[j + 1], kC9CoefsLow[j + 2], t);
    } else if (logx < kC9LogMaxX) {
        float knot = float(kKnotsHigh - 1) * (logx - kC9LogMidX) / (kC9LogMaxX - kC9LogMidX);
        int j = min(int(knot), kKnotsHigh - 1);
        float t = knot - float(j);
        logy = tmAcesSplineSegment(kC9CoefsHigh[j], kC9CoefsHigh[j + 1], kC9CoefsHigh[j + 2], t);
    } else {
        logy = logx * kC9SlopeHigh + (kC9LogMaxY - kC9SlopeHigh * kC9LogMaxX);
    }
    return tmAcesPow10(logy);
}

float tmAcesRgbToSaturation(vec3 rgb) {
    const float kTiny = 1e-10;
    float mx = max(rgb.r, max(rgb.g, rgb.b));
    float mn = min(rgb.r, min(rgb.g, rgb.b));
    return (max(mx, kTiny) - max(mn, kTiny)) / max(mx, 1e-2);
}

float tmAcesRgbToYc(vec3 rgb) {
    const float kYcRadiusWeight = 1.75;
    float chroma =
        sqrt(max(rgb.b * (rgb.b - rgb.g) + rgb.g * (rgb.g - rgb.r) + rgb.r * (rgb.r - rgb.b), 0.0));
    return (rgb.b + rgb.g + rgb.r + kYcRadiusWeight * chroma) / 3.0;
}

float tmAcesSigmoidShaper(float x) {
    float t = max(1.0 - abs(x / 2.0), 0.0);
    float y = 1.0 + sign(x) * (1.0 - t * t);
    return y / 2.0;
}

float tmAcesGlowFwd(float ycIn, float glowGainIn, float glowMid) {
    if (ycIn <= 2.0 / 3.0 * glowMid) {
        return glowGainIn;
    }
    if (ycIn >= 2.0 * glowMid) {
        return 0.0;
    }
    return glowGainIn * (glowMid / ycIn - 1.0 / 2.0);
}

// Only called for non-neutral colours, so atan's arguments are never both 0.
float tmAcesRgbToHue(vec3 rgb) {
    const float kSqrt3 = 1.7320508076;
    const float kRadToDeg = 57.2957795131;
    float hue = kRadToDeg * atan(kSqrt3 * (rgb.g - rgb.b), 2.0 * rgb.r - rgb.g - rgb.b);
    if (hue < 0.0) {
        hue = hue + 360.0;
    }
    return hue;
}

float tmAcesCenterHue(float hue, float centerH) {
    float hueCentered = hue - centerH;
    if (hueCentered < -180.0) {
        hueCentered = hueCentered + 360.0;
    } else if (hueCentered > 180.0) {
        hueCentered = hueCentered - 360.0;
    }
    return hueCentered;
}

float tmAcesCubicBasisShaper(float x, float w) {
    float y = 0.0;
    if (x > -w / 2.0 && x < w / 2.0) {
        float knot = (x + w / 2.0) * 4.0 / w;
        int j = int(knot);
        float t = knot - float(j);
        float m0 = t * t * t;
        float m1 = t * t;
        float m2 = t;
        if (j == 3) {
            y = m0 * (-1.0 / 6.0) + m1 * (3.0 / 6.0) + m2 * (-3.0 / 6.0) + 1.0 / 6.0;
        } else if (j == 2) {
            y = m0 * (3.0 / 6.0) + m1 * (-6.0 / 6.0) + m2 * (0.0 / 6.0) + 4.0 / 6.0;
        } else if (j == 1) {
            y = m0 * (-3.0 / 6.0) + m1 * (3.0 / 6.0) + m2 * (3.0 / 6.0) + 1.0 / 6.0;
        } else if (j == 0) {
            y = m0 * (1.0 / 6.0);
        }
    }
    return y * 3.0 / 2.0;
}

vec3 tmAcesDarkToDimSurround(vec3 linearCV) {
    const float kDimSurroundGamma = 0.9811;
    vec3 xyz = kAcesAp1ToXyz * linearCV;
    float divisor = xyz.x + xyz.y + xyz.z;
    if (divisor == 0.0) {
        divisor = 1e-10;
    }
    vec3 xyY = vec3(xyz.x / divisor, xyz.y / divisor, xyz.y);
    xyY.z = max(xyY.z, 0.0);
    xyY.z = pow(xyY.z, kDimSurroundGamma);
    xyz = vec3(xyY.x * xyY.z / max(xyY.y, 1e-10), xyY.z, (1.0 - xyY.x - xyY.y) * xyY.z / max(xyY.y, 1e-10));
    return kAcesXyzToAp1 * xyz;
}

vec3 tmAces(vec3 rgb) {
    vec3 ap0 = kAcesRec709ToAp0 * rgb;

    // RRT: glow module.
    float saturation = tmAcesRgbToSaturation(ap0);
    float ycIn = tmAcesRgbToYc(ap0);
    float s = tmAcesSigmoidShaper((saturation - 0.4) / 0.2);
    float addedGlow = 1.0 + tmAcesGlowFwd(ycIn, kAcesGlowGain * s, kAcesGlowMid);
    ap0 = addedGlow * ap0;

    // RRT: red modifier (weight 0 for neutrals, whose CTL hue is NaN).
    float hueWeight = 0.0;
    if (!(ap0.r == ap0.g && ap0.g == ap0.b)) {
        float hue = tmAcesRgbToHue(ap0);
        float centeredHue = tmAcesCenterHue(hue, kAcesRedHue);
        hueWeight = tmAcesCubicBasisShaper(centeredHue, kAcesRedWidth);
    }
    ap0.r = ap0.r + hueWeight * saturation * (kAcesRedPivot - ap0.r) * (1.0 - kAcesRedScale);

    // RRT: AP1 rendering space, global desaturation, tone scale.
    ap0 = max(ap0, vec3(0.0));
    vec3 rgbPre = clamp(kAcesAp0ToAp1 * ap0, vec3(0.0), vec3(kTmHalfMax));
    rgbPre = kAcesRrtSat * rgbPre;
    vec3 rgbPost = vec3(tmAcesSplineC5(rgbPre.r), tmAcesSplineC5(rgbPre.g), tmAcesSplineC5(rgbPre.b));

    // ODT sRGB 100 nits dim (the RRT's AP1 -> AP0 and the ODT's AP0 -> AP1 cancel).
    vec3 odtPost = vec3(tmAcesSplineC9(rgbPost.r), tmAcesSplineC9(rgbPost.g), tmAcesSplineC9(rgbPost.b));

    float cinemaWhite = 48.0;
    float cinemaBlack = tmAcesPow10(kC9LogMinY);
    vec3 linearCV = (odtPost - cinemaBlack) / (cinemaWhite - cinemaBlack);
    linearCV = max(linearCV, vec3(0.0));

    linearCV = tmAcesDarkToDimSurround(linearCV);
    linearCV = kAcesOdtSat * linearCV;
    linearCV = kAcesAp1ToRec709 * linearCV;
    return clamp(linearCV, vec3(0.0), vec3(1.0));
}

// -------------------------------------------------------------------------------- AgX
const mat3 kAgxInset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
const mat3 kAgxOutset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
const float kAgxMinEv = -12.47393;
const float kAgxMaxEv = 4.026069;

vec3 tmAgxContrastApprox(vec3 x) {
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return +15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x -
           0.00232;
}

vec3 tmAgxLogEncode(vec3 x) {
    x = clamp(log2(max(x, vec3(1e-10))), vec3(kAgxMinEv), vec3(kAgxMaxEv));
    return (x - kAgxMinEv) / (kAgxMaxEv - kAgxMinEv);
}

// ASC CDL order: slope/offset/power, then saturation around the luma of that result (see ToneCurves.cpp).
vec3 tmAgxLook(vec3 val, int look) {
    vec3 offset = vec3(0.0);
    vec3 slope = vec3(1.0);
    vec3 power = vec3(1.0);
    float sat = 1.0;
    if (look == AGX_LOOK_GOLDEN) {
        slope = vec3(1.0, 0.9, 0.5);
        power = vec3(0.8);
        sat = 0.8;
    } else if (look == AGX_LOOK_PUNCHY) {
        slope = vec3(1.0);
        power = vec3(1.35);
        sat = 1.4;
    }
    val = pow(max(val * slope + offset, vec3(0.0)), power);
    const vec3 lw = vec3(0.2126, 0.7152, 0.0722);
    float luma = dot(val, lw);
    return luma + sat * (val - luma);
}

vec3 tmAgx(vec3 x, int look) {
    vec3 v = kAgxInset * x;
    v = tmAgxLogEncode(v);
    v = tmAgxContrastApprox(v);
    if (look != AGX_LOOK_BASE) {
        v = tmAgxLook(v, look);
    }
    v = kAgxOutset * v;
    return pow(max(v, vec3(0.0)), vec3(2.2));
}

// -------------------------------------------------------------------------------- PBR Neutral
vec3 tmNeutral(vec3 color) {
    const float kStartCompression = 0.8 - 0.04;
    const float kDesaturation = 0.15;

    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;

    float peak = max(color.r, max(color.g, color.b));
    if (peak < kStartCompression) {
        return color;
    }

    float d = 1.0 - kStartCompression;
    float newPeak = 1.0 - d * d / (peak + d - kStartCompression);
    color *= newPeak / peak;

    float g = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

// -------------------------------------------------------------------------------- entry point
// mode: TONEMAP_*; whitePoint: reinhard-extended W (scene-linear); agxLook: AGX_LOOK_*.
vec3 toneMap(int mode, vec3 x, float whitePoint, int agxLook) {
    x = clamp(x, vec3(0.0), vec3(kTmHalfMax));
    vec3 y = vec3(0.0);
    switch (mode) {
    case TONEMAP_LINEAR:
        y = x;
        break;
    case TONEMAP_REINHARD:
        y = tmReinhard(x);
        break;
    case TONEMAP_REINHARD_EXTENDED:
        y = tmReinhardExtended(x, whitePoint);
        break;
    case TONEMAP_HABLE:
        y = tmHable(x);
        break;
    case TONEMAP_LOTTES:
        y = tmLottes(x);
        break;
    case TONEMAP_UCHIMURA:
        y = tmUchimura(x);
        break;
    case TONEMAP_ACES_NARKOWICZ:
        y = tmAcesNarkowicz(x);
        break;
    case TONEMAP_ACES_FITTED:
        y = tmAcesFitted(x);
        break;
    case TONEMAP_ACES:
        y = tmAces(x);
        break;
    case TONEMAP_AGX:
        y = tmAgx(x, agxLook);
        break;
    case TONEMAP_NEUTRAL:
        y = tmNeutral(x);
        break;
    }
    return clamp(y, vec3(0.0), vec3(1.0));
}

#endif // PHOTOPIC_TONECURVES_H_GLSL
