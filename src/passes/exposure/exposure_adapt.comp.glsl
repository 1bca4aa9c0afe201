// Exposure target and adaptation on the GPU, one group per frame: reads this frame's metering
// (passes/metering/), writes the exposure state every later pass reads. With a histogram, the group's 256
// invocations take one bin each for the percentile statistics (histogramStatistics); the rest is one
// invocation's work; the bins are copied into shared memory first, since one invocation reading all 256 from
// the buffer in turn was what the pass's time went on. A line-for-line mirror of core/ExposureController.cpp (target, adaptExposure with deadband
// hysteresis, dt clamp, snap, exposureMultiplier, ExposureController::update) and core/Metering.cpp
// (histogramAverage), in float32 with exp, exp2, log2, min, max. Models: exponential eye lag
// (tauBrighten/tauDarken), a speed form (alpha = 1 - exp(-speed dt)), Unreal's eye adaptation (hybrid: linear
// then exponential). Tardif 2019 for the histogram percentiles.
#define EXPOSURE_STATE_WRITABLE 1
#include "passes/common/exposure.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"

layout(local_size_x = 256) in;

shared uint sBins[256];

const float kExposureMinLuminance = 1e-4; // core: kExposureMinLuminance
const float kDeadbandExitFraction = 0.1;  // core: kDeadbandExitFraction
const float kManualEVLimit = 64.0;        // core: kManualEVLimit
const float kMinDivisor = 1e-6;           // core: kMinDivisor
const int kAdaptExponential = 0;
const int kAdaptSpeed = 1;
const int kAdaptHybrid = 2;

// Mirrors photopic::ExposureParameters (passes/exposure/ExposurePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform ExposureParameters {
    int uAutoEnabled;
    int uMetered;        // 1: metering ran for exposure this frame (a reading may exist)
    int uHistogramBuilt; // 1: gBins holds this frame's histogram
    int uMeteringMode;   // core MeteringMode
    int uReset;          // 1: resetExposure() or resize: the next valid reading snaps
    float uDt;
    float uManualEV;

    float uKeyValue;
    float uCompensationEV;
    float uMinEV;
    float uMaxEV;
    vec2 uCurve[16]; // std140: each element padded to 16 bytes
    int uCurveCount;
    int uAdaptation;
    float uTauBrighten;
    float uTauDarken;
    float uSpeedUp;
    float uSpeedDown;
    float uTransitionEV;
    float uDeadbandEV;
    float uMaxDt;
    float uLog2Min;
    float uLog2Max;
    float uLowPercent;
    float uHighPercent;
    int uOverride;       // 1: the host planned this frame's auto exposure (uOverrideLog2)
    float uOverrideLog2;  // EV, replaces the adapted value
};

// core: compensationCurveEV.
float compensationCurveEV(float x) {
    if (uCurveCount <= 0) {
        return 0.0;
    }
    if (x <= uCurve[0].x) {
        return uCurve[0].y;
    }
    for (int i = 1; i < uCurveCount; ++i) {
        if (x < uCurve[i].x) {
            vec2 a = uCurve[i - 1];
            vec2 b = uCurve[i];
            float t = (x - a.x) / (b.x - a.x);
            return a.y + (b.y - a.y) * t;
        }
    }
    return uCurve[uCurveCount - 1].y;
}

// core: exposureTargetLog2.
float exposureTargetLog2(float luminance) {
    float l = luminance > kExposureMinLuminance ? luminance : kExposureMinLuminance;
    float x = log2(l);
    float target = log2(uKeyValue) - x + uCompensationEV + compensationCurveEV(x);
    return min(max(target, uMinEV), uMaxEV);
}

// core: hybridRemaining.
float hybridRemaining(float g, float speed, float h) {
    float s = max(speed, kMinDivisor);
    float d = max(uTransitionEV, kMinDivisor);
    float k = s / d;
    if (g > d) {
        float tLinear = (g - d) / s;
        if (h <= tLinear) {
            return g - s * h;
        }
        return d * exp(-k * (h - tLinear));
    }
    return g * exp(-k * h);
}

// core: adaptExposure (the caller has checked the target is finite).
void adaptExposure(float target, float dt) {
    float prevApplied = gExposure.appliedLog2;
    gExposure.targetLog2 = target;
    if (gExposure.initialized == 0 || !isFiniteBits(prevApplied)) {
        gExposure.appliedLog2 = target;
        gExposure.adapting = 0;
        gExposure.initialized = 1;
        return;
    }
    float h = dt > 0.0 ? min(dt, uMaxDt) : 0.0;
    float gap = target - prevApplied;
    float absGap = abs(gap);
    if (gExposure.adapting == 0 && absGap > uDeadbandEV) {
        gExposure.adapting = 1;
    } else if (gExposure.adapting != 0 && absGap < kDeadbandExitFraction * uDeadbandEV) {
        gExposure.adapting = 0;
    }
    if (gExposure.adapting != 0) {
        bool rising = gap > 0.0; // exposure goes up: the scene got darker
        if (uAdaptation == kAdaptExponential) {
            float tau = max(rising ? uTauBrighten : uTauDarken, kMinDivisor);
            float alpha = clamp(1.0 - exp(-h / tau), 0.0, 1.0);
            gExposure.appliedLog2 = prevApplied + gap * alpha;
        } else if (uAdaptation == kAdaptSpeed) {
            float speed = rising ? uSpeedDown : uSpeedUp;
            float alpha = clamp(1.0 - exp(-speed * h), 0.0, 1.0);
            gExposure.appliedLog2 = prevApplied + gap * alpha;
        } else {
            float speed = rising ? uSpeedDown : uSpeedUp;
            float r = hybridRemaining(absGap, speed, h);
            gExposure.appliedLog2 = rising ? target - r : target + r;
        }
    }
}

// core: exposureMultiplier.
float exposureMultiplier(float manualEV) {
    float manual = isFiniteBits(manualEV) ? clamp(manualEV, -kManualEVLimit, kManualEVLimit) : 0.0;
    if (uAutoEnabled != 0 && gExposure.initialized != 0) {
        return exp2(manual + gExposure.appliedLog2);
    }
    return exp2(manual);
}

// core: histogramAverage over the bins (sBins, this frame's gBins); writes the histogram fields of the state,
// returns the average (log2). The group's 256 invocations, one per bin, run everything but the two float
// sums: the count and the peak (integers), each bin's place in the cumulative count (an integer scan, exact
// as the CPU's running count is), its weight inside the percentile window and its centre, and the first bins
// past the low and high percentiles. One invocation then adds the weighted centres in the CPU's order, so the
// average is the CPU's to the bit. Called by the whole group (it holds barriers).
shared uint sScan[256];
shared float sWeight[256];
shared float sCentre[256];
shared uint sTotal;
shared uint sPeak;
shared uint sLowBin;
shared uint sHighBin;

float histogramStatistics() {
    uint b = gl_LocalInvocationIndex;
    uint count = sBins[b];
    sScan[b] = count;
    if (b == 0u) {
        sPeak = 0u;
        sLowBin = 256u;
        sHighBin = 256u;
    }
    barrier();
    atomicMax(sPeak, count);
    for (uint offset = 1u; offset < 256u; offset *= 2u) { // inclusive scan (Hillis and Steele)
        uint earlier = b >= offset ? sScan[b - offset] : 0u;
        barrier();
        sScan[b] += earlier;
        barrier();
    }
    uint total = sScan[255];
    float n = float(total);
    float lo = n * (clamp(uLowPercent, 0.0, 100.0) * 0.01);
    float hi = n * (clamp(uHighPercent, 0.0, 100.0) * 0.01);
    float cumulative = float(sScan[b]);
    float start = float(sScan[b] - count);
    sCentre[b] = histogramBinCentreLog2(int(b), uLog2Min, uLog2Max);
    sWeight[b] = max(0.0, min(cumulative, hi) - max(start, lo));
    if (count > 0u && cumulative > lo) {
        atomicMin(sLowBin, b);
    }
    if (count > 0u && cumulative >= hi) {
        atomicMin(sHighBin, b);
    }
    barrier();
    if (b != 0u) {
        return 0.0;
    }
    gExposure.histogramCount = total;
    gExposure.histogramPeak = sPeak;
    gExposure.histogramLowLog2 = 0.0;
    gExposure.histogramHighLog2 = 0.0;
    gExposure.histogramAverageLog2 = 0.0;
    if (total == 0u) {
        return 0.0;
    }
    // `precise` and divideRounded: the CPU's roundings, a multiply and an add apart (no fma) and a rounded
    // quotient.
    precise float sum = 0.0;
    precise float weightSum = 0.0;
    for (int i = 0; i < kHistogramBins; ++i) {
        float w = sWeight[i];
        sum += w * sCentre[i];
        weightSum += w;
    }
    float lowLog2 = sLowBin < 256u ? sCentre[sLowBin] : 0.0;
    float highLog2 = sHighBin < 256u ? sCentre[sHighBin] : 0.0;
    float average = weightSum > 0.0 ? divideRounded(sum, weightSum) : lowLog2;
    gExposure.histogramLowLog2 = lowLog2;
    gExposure.histogramHighLog2 = highLog2;
    gExposure.histogramAverageLog2 = average;
    return average;
}

// core: ExposureController::update, with this frame's reading.
void followReading(float reading) {
    if (!isMeterable(reading)) {
        gExposure.frameLuminance = 0.0;
        gExposure.exposure = exposureMultiplier(uManualEV);
        return;
    }
    gExposure.frameLuminance = reading;
    float target = exposureTargetLog2(reading);
    if (uAutoEnabled == 0) {
        gExposure.meteredLuminance = reading;
        gExposure.targetLog2 = target;
        gExposure.adapting = 0;
        gExposure.initialized = 0;
    } else if (isFiniteBits(target)) {
        adaptExposure(target, uDt);
        gExposure.meteredLuminance = reading;
    }
    gExposure.exposure = exposureMultiplier(uManualEV);
}

void main() {
    sBins[gl_LocalInvocationIndex] = gBins[gl_LocalInvocationIndex];
    barrier();
    float histogramAverage = uHistogramBuilt != 0 ? histogramStatistics() : 0.0; // the whole group's work
    if (gl_LocalInvocationIndex != 0u) {
        return; // the rest is one invocation's work, in the CPU's order
    }
    if (uReset != 0) {
        gExposure.adapting = 0;
        gExposure.initialized = 0;
    }
    gExposure.manualEV = uManualEV;
    gExposure.autoEnabled = uAutoEnabled;

    if (uHistogramBuilt == 0) {
        gExposure.histogramCount = 0u;
        gExposure.histogramPeak = 0u;
        gExposure.histogramLowLog2 = 0.0;
        gExposure.histogramHighLog2 = 0.0;
        gExposure.histogramAverageLog2 = 0.0;
    }
    bool anyMeterable = (uMetered != 0 || uHistogramBuilt != 0) && gMaxBits != 0u;
    gExposure.minLuminance = anyMeterable ? uintBitsToFloat(gMinBits) : 0.0;
    gExposure.maxLuminance = anyMeterable ? uintBitsToFloat(gMaxBits) : 0.0;

    float reading = 0.0;
    if (uMetered != 0) {
        if (uMeteringMode == kMeterHistogram) {
            reading = gExposure.histogramCount > 0u ? exp2(histogramAverage) : 0.0;
        } else {
            reading = gReading;
        }
    }
    followReading(reading);
    // A planned exposure (a sequence rendered in chunks with the whole sequence's plan): the target and the
    // readings above stay this frame's own for telemetry; the applied value is the plan's.
    if (uOverride != 0) {
        float manual = isFiniteBits(uManualEV) ? clamp(uManualEV, -kManualEVLimit, kManualEVLimit) : 0.0;
        gExposure.appliedLog2 = uOverrideLog2;
        gExposure.adapting = 0;
        gExposure.initialized = 1;
        gExposure.exposure = exp2(manual + uOverrideLog2);
    }
}
