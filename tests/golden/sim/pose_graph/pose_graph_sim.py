# generated from template sim.py.jinja by fgc — do not edit
# fgc 0.1.0
"""Simulator of the fgc accelerator for problem pose_graph.

The structure is compiled in: 5 variables, 7 factor block instances
of 2 block types, a general elimination schedule of 3 steps in
2 levels, solver lm-qr-auto-float32. Measurements, noise and initial values come from a data
file (fgc's run-time data format).

    python pose_graph_sim.py DATA RESULT.json [--precision float32|float64]
        [--incremental | --window W | --policy JSON]
"""

import argparse
import hashlib
import importlib.util
import json
import os
import sys
import types

import numpy


def _load(name):
    """A run-time (or the constants) module emitted next to this file, loaded once per file
    content."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name + ".py")
    with open(path, "rb") as handle:
        key = f"_fgc_sim_{hashlib.sha256(handle.read()).hexdigest()[:16]}_{name}"
    if key not in sys.modules:
        spec = importlib.util.spec_from_file_location(key, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        sys.modules[key] = module
    return sys.modules[key]


LIB = types.SimpleNamespace(**{name: _load(f"fgc_sim_{name}")
                               for name in ("constants", "special", "linear", "runtime",
                                            "optimizer", "incremental", "diagnostics")})
so3_log = LIB.special.so3_log
LIE = LIB.special.lie_functions(LIB.constants.SERIES_BELOW, LIB.constants.SERIES,
                                _load("lie_closed_forms"))
lie_A = LIE["A"]
lie_A1 = LIE["A1"]
lie_B = LIE["B"]
lie_B1 = LIE["B1"]
lie_C = LIE["C"]
lie_C1 = LIE["C1"]
lie_D = LIE["D"]
lie_D1 = LIE["D1"]


# --------------------------------------------------------------------------------------------
# block kernels: x is (inputs × instances), out is (outputs × instances)
# --------------------------------------------------------------------------------------------


def jacobian_0(x):
    """Block type 0 (BetweenFactorPose3), error + Jacobian mode: residual (6) then
    each variable's Jacobian, row-major; 371 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    a18 = x[18]
    a19 = x[19]
    a20 = x[20]
    a21 = x[21]
    a22 = x[22]
    a23 = x[23]
    a24 = x[24]
    a25 = x[25]
    a26 = x[26]
    a27 = x[27]
    a28 = x[28]
    a29 = x[29]
    a30 = x[30]
    a31 = x[31]
    a32 = x[32]
    a33 = x[33]
    a34 = x[34]
    a35 = x[35]
    t0 = a0*a12 + a15*a3 + a18*a6
    t1 = a12*a2 + a15*a5 + a18*a8
    t2 = -t1
    t3 = a1*a12 + a15*a4 + a18*a7
    t4 = a0*a14 + a17*a3 + a20*a6
    t5 = -t4
    t6 = a0*a13 + a16*a3 + a19*a6
    t7 = -t0
    t8 = a1*a14 + a17*a4 + a20*a7
    t9 = -t8
    t10 = a1*a13 + a16*a4 + a19*a7
    t11 = -t3
    t12 = a14*a2 + a17*a5 + a20*a8
    t13 = -t12
    t14 = a13*a2 + a16*a5 + a19*a8
    t15 = -t14
    t16 = -t6
    t17 = -t10
    t18 = t0
    t19 = t3
    t20 = t1
    t21 = a24*t18 + a27*t19 + a30*t20
    t22 = t6
    t23 = t10
    t24 = t14
    t25 = a24*t22 + a27*t23 + a30*t24
    t26 = t4
    t27 = t8
    t28 = t12
    t29 = a24*t26 + a27*t27 + a30*t28
    t30 = a25*t18 + a28*t19 + a31*t20
    t31 = a25*t22 + a28*t23 + a31*t24
    t32 = a25*t26 + a28*t27 + a31*t28
    t33 = a26*t18 + a29*t19 + a32*t20
    t34 = a26*t22 + a29*t23 + a32*t24
    t35 = a26*t26 + a29*t27 + a32*t28
    w0_0, w0_1, w0_2 = so3_log(t21, t25, t29, t30, t31, t32, t33, t34, t35)
    t36 = w0_2
    t37 = (0.5)*t36
    t38 = w0_0
    t39 = t38**2
    t40 = w0_1
    t41 = t40**2
    t42 = t36**2
    t43 = t41 + t42
    t44 = lie_D(t39 + t43)
    t45 = t38*t44
    t46 = t40*t45
    t47 = -t37 + t46
    t48 = (0.5)*t29
    t49 = (0.5)*t40
    t50 = t36*t45
    t51 = t49 + t50
    t52 = (0.5)*t25*t51 - t47*t48
    t53 = -t43*t44 + 1
    t54 = (0.5)*t51
    t55 = -t21*t54 + t48*t53
    t56 = (0.5)*t47
    t57 = (0.5)*t53
    t58 = t21*t56 - t25*t57
    t59 = t31*t54 - t32*t56
    t60 = -t30*t54 + (0.5)*t32*t53
    t61 = t30*t56 - t31*t57
    t62 = t34*t54 - t35*t56
    t63 = -t33*t54 + (0.5)*t35*t53
    t64 = t33*t56 - t34*t57
    t65 = t44*(-t39 - t42) + 1
    t66 = (0.5)*t38
    t67 = t36*t40*t44 - t66
    t68 = (0.5)*t25*t67 - t48*t65
    t69 = t37 + t46
    t70 = (0.5)*t67
    t71 = -t21*t70 + t48*t69
    t72 = (0.5)*t65
    t73 = (0.5)*t69
    t74 = t21*t72 - t25*t73
    t75 = t31*t70 - t32*t72
    t76 = -t30*t70 + (0.5)*t32*t69
    t77 = t30*t72 - t31*t73
    t78 = t34*t70 - t35*t72
    t79 = -t33*t70 + (0.5)*t35*t69
    t80 = t33*t72 - t34*t73
    t81 = t36*t40
    t82 = t44*t81 + t66
    t83 = t44*(-t39 - t41) + 1
    t84 = (0.5)*t25*t83 - t48*t82
    t85 = -t49 + t50
    t86 = (0.5)*t83
    t87 = -t21*t86 + t48*t85
    t88 = (0.5)*t82
    t89 = (0.5)*t85
    t90 = t21*t88 - t25*t89
    t91 = t31*t86 - t32*t88
    t92 = -t30*t86 + (0.5)*t32*t85
    t93 = t30*t88 - t31*t89
    t94 = t34*t86 - t35*t88
    t95 = -t33*t86 + (0.5)*t35*t85
    t96 = t33*t88 - t34*t89
    t97 = 2*t40
    t98 = 2*t36
    t99 = 2*t38
    t100 = t41
    t101 = t42
    t102 = t100 + t101
    t103 = t39
    t104 = t102 + t103
    t105 = lie_D1(t104)
    t106 = a21 - a9
    t107 = -a10 + a22
    t108 = -a11 + a23
    t109 = a2*t106 + a5*t107 + a8*t108
    t110 = a1*t106 + a4*t107 + a7*t108
    t111 = -a0*a1 - a3*a4 - a6*a7
    t112 = -a0*a2 - a3*a5 - a6*a8
    t113 = a0*t106 + a3*t107 + a6*t108
    t114 = -a1*a2 - a4*a5 - a7*a8
    t115 = lie_D(t104)
    t116 = t115*t40
    t117 = t115*t36
    t118 = -t102*t115 + 1
    t119 = t37
    t120 = t115*t38
    t121 = t120*t40
    t122 = t119 + t121
    t123 = t49
    t124 = t120*t36
    t125 = -t123 + t124
    t126 = -t119 + t121
    t127 = -t101 - t103
    t128 = t115*t127 + 1
    t129 = t66
    t130 = t115*t81
    t131 = t129 + t130
    t132 = t123 + t124
    t133 = -t129 + t130
    t134 = -t100 - t103
    t135 = t115*t134 + 1
    t136 = a0*a21 - a0*a9 - a10*a3 - a11*a6 + a22*a3 + a23*a6
    t137 = a1*a21 - a1*a9 - a10*a4 - a11*a7 + a22*a4 + a23*a7
    t138 = -a10*a5 - a11*a8 + a2*a21 - a2*a9 + a22*a5 + a23*a8
    t139 = -a24*a33 + a24*t136 - a27*a34 + a27*t137 - a30*a35 + a30*t138
    t140 = t102*t139
    t141 = t115*t139
    t142 = -a25*a33 + a25*t136 - a28*a34 + a28*t137 - a31*a35 + a31*t138
    t143 = t127*t142
    t144 = t115*t142
    t145 = -a26*a33 + a26*t136 - a29*a34 + a29*t137 - a32*a35 + a32*t138
    t146 = t134*t145
    t147 = t115*t145
    t148 = t2
    t149 = t3
    t150 = t5
    t151 = t6
    t152 = t1
    t153 = t7
    t154 = t9
    t155 = t10
    t156 = t11
    t157 = t0
    t158 = t13
    t159 = t14
    t160 = a27*t152 + a30*t156
    t161 = a24*t148 + a30*t157
    t162 = a24*t149 + a27*t153
    t163 = a24*t150 + a27*t154 + a30*t158
    t164 = a24*t151 + a27*t155 + a30*t159
    t165 = t15
    t166 = t10
    t167 = t4
    t168 = t7
    t169 = t14
    t170 = t16
    t171 = t8
    t172 = t11
    t173 = t17
    t174 = t6
    t175 = t12
    t176 = t2
    t177 = a27*t169 + a30*t173
    t178 = a24*t165 + a30*t174
    t179 = a24*t166 + a27*t170
    t180 = a24*t167 + a27*t171 + a30*t175
    t181 = a24*t168 + a27*t172 + a30*t176
    t182 = t13
    t183 = t8
    t184 = t16
    t185 = t0
    t186 = t12
    t187 = t5
    t188 = t17
    t189 = t3
    t190 = t9
    t191 = t4
    t192 = t15
    t193 = t1
    t194 = a27*t186 + a30*t190
    t195 = a24*t182 + a30*t191
    t196 = a24*t183 + a27*t187
    t197 = a24*t184 + a27*t188 + a30*t192
    t198 = a24*t185 + a27*t189 + a30*t193
    t199 = a28*t152 + a31*t156
    t200 = a25*t148 + a31*t157
    t201 = a25*t149 + a28*t153
    t202 = a25*t150 + a28*t154 + a31*t158
    t203 = a25*t151 + a28*t155 + a31*t159
    t204 = a28*t169 + a31*t173
    t205 = a25*t165 + a31*t174
    t206 = a25*t166 + a28*t170
    t207 = a25*t167 + a28*t171 + a31*t175
    t208 = a25*t168 + a28*t172 + a31*t176
    t209 = a28*t186 + a31*t190
    t210 = a25*t182 + a31*t191
    t211 = a25*t183 + a28*t187
    t212 = a25*t184 + a28*t188 + a31*t192
    t213 = a25*t185 + a28*t189 + a31*t193
    t214 = a29*t152 + a32*t156
    t215 = a26*t148 + a32*t157
    t216 = a26*t149 + a29*t153
    t217 = a26*t150 + a29*t154 + a32*t158
    t218 = a26*t151 + a29*t155 + a32*t159
    t219 = a29*t169 + a32*t173
    t220 = a26*t165 + a32*t174
    t221 = a26*t166 + a29*t170
    t222 = a26*t167 + a29*t171 + a32*t175
    t223 = a26*t168 + a29*t172 + a32*t176
    t224 = a29*t186 + a32*t190
    t225 = a26*t182 + a32*t191
    t226 = a26*t183 + a29*t187
    t227 = a26*t184 + a29*t188 + a32*t192
    t228 = a26*t185 + a29*t189 + a32*t193
    t229 = t160*t52 + t177*t55 + t194*t58 + t199*t59 + t204*t60 + t209*t61 + t214*t62 + t219*t63 + t224*t64
    t230 = t161*t52 + t178*t55 + t195*t58 + t200*t59 + t205*t60 + t210*t61 + t215*t62 + t220*t63 + t225*t64
    t231 = t162*t52 + t179*t55 + t196*t58 + t201*t59 + t206*t60 + t211*t61 + t216*t62 + t221*t63 + t226*t64
    t232 = t180*t55 + t197*t58 + t207*t60 + t212*t61 + t222*t63 + t227*t64
    t233 = t163*t52 + t198*t58 + t202*t59 + t213*t61 + t217*t62 + t228*t64
    t234 = t164*t52 + t181*t55 + t203*t59 + t208*t60 + t218*t62 + t223*t63
    t235 = t160*t68 + t177*t71 + t194*t74 + t199*t75 + t204*t76 + t209*t77 + t214*t78 + t219*t79 + t224*t80
    t236 = t161*t68 + t178*t71 + t195*t74 + t200*t75 + t205*t76 + t210*t77 + t215*t78 + t220*t79 + t225*t80
    t237 = t162*t68 + t179*t71 + t196*t74 + t201*t75 + t206*t76 + t211*t77 + t216*t78 + t221*t79 + t226*t80
    t238 = t180*t71 + t197*t74 + t207*t76 + t212*t77 + t222*t79 + t227*t80
    t239 = t163*t68 + t198*t74 + t202*t75 + t213*t77 + t217*t78 + t228*t80
    t240 = t164*t68 + t181*t71 + t203*t75 + t208*t76 + t218*t78 + t223*t79
    t241 = t160*t84 + t177*t87 + t194*t90 + t199*t91 + t204*t92 + t209*t93 + t214*t94 + t219*t95 + t224*t96
    t242 = t161*t84 + t178*t87 + t195*t90 + t200*t91 + t205*t92 + t210*t93 + t215*t94 + t220*t95 + t225*t96
    t243 = t162*t84 + t179*t87 + t196*t90 + t201*t91 + t206*t92 + t211*t93 + t216*t94 + t221*t95 + t226*t96
    t244 = t180*t87 + t197*t90 + t207*t92 + t212*t93 + t222*t95 + t227*t96
    t245 = t163*t84 + t198*t90 + t202*t91 + t213*t93 + t217*t94 + t228*t96
    t246 = t164*t84 + t181*t87 + t203*t91 + t208*t92 + t218*t94 + t223*t95
    t247 = t235*t97
    t248 = t236*t97
    t249 = t237*t97
    t250 = t238*t97
    t251 = t239*t97
    t252 = t240*t97
    t253 = t241*t98
    t254 = t242*t98
    t255 = t243*t98
    t256 = t244*t98
    t257 = t245*t98
    t258 = t246*t98
    t259 = t247 + t253
    t260 = t248 + t254
    t261 = t249 + t255
    t262 = t250 + t256
    t263 = t251 + t257
    t264 = t252 + t258
    t265 = t229*t99
    t266 = t230*t99
    t267 = t231*t99
    t268 = t232*t99
    t269 = t233*t99
    t270 = t234*t99
    t271 = t105*t259 + t105*t265
    t272 = t105*t260 + t105*t266
    t273 = t105*t261 + t105*t267
    t274 = t105*t262 + t105*t268
    t275 = t105*t263 + t105*t269
    t276 = t105*t264 + t105*t270
    t277 = -t109
    t278 = t110
    t279 = -a0**2 - a3**2 - a6**2
    t280 = t111
    t281 = t112
    t282 = t0
    t283 = t6
    t284 = t4
    t285 = t109
    t286 = -t113
    t287 = t111
    t288 = -a1**2 - a4**2 - a7**2
    t289 = t114
    t290 = t3
    t291 = t10
    t292 = t8
    t293 = -t110
    t294 = t113
    t295 = t112
    t296 = t114
    t297 = -a2**2 - a5**2 - a8**2
    t298 = t1
    t299 = t14
    t300 = t12
    t301 = a27*t285 + a30*t293
    t302 = a24*t277 + a30*t294
    t303 = a24*t278 + a27*t286
    t304 = a24*t279 + a27*t287 + a30*t295
    t305 = a24*t280 + a27*t288 + a30*t296
    t306 = a24*t281 + a27*t289 + a30*t297
    t307 = a24*t282 + a27*t290 + a30*t298
    t308 = a24*t283 + a27*t291 + a30*t299
    t309 = a24*t284 + a27*t292 + a30*t300
    t310 = (0.5)*t241
    t311 = (0.5)*t242
    t312 = (0.5)*t243
    t313 = (0.5)*t244
    t314 = (0.5)*t245
    t315 = (0.5)*t246
    t316 = t115*t229 + t271*t38
    t317 = t115*t230 + t272*t38
    t318 = t115*t231 + t273*t38
    t319 = t115*t232 + t274*t38
    t320 = t115*t233 + t275*t38
    t321 = t115*t234 + t276*t38
    t322 = t120*t235 + t316*t40
    t323 = t120*t236 + t317*t40
    t324 = t120*t237 + t318*t40
    t325 = t120*t238 + t319*t40
    t326 = t120*t239 + t320*t40
    t327 = t120*t240 + t321*t40
    t328 = a28*t285 + a31*t293
    t329 = a25*t277 + a31*t294
    t330 = a25*t278 + a28*t286
    t331 = a25*t279 + a28*t287 + a31*t295
    t332 = a25*t280 + a28*t288 + a31*t296
    t333 = a25*t281 + a28*t289 + a31*t297
    t334 = a25*t282 + a28*t290 + a31*t298
    t335 = a25*t283 + a28*t291 + a31*t299
    t336 = a25*t284 + a28*t292 + a31*t300
    t337 = (0.5)*t235
    t338 = (0.5)*t236
    t339 = (0.5)*t237
    t340 = (0.5)*t238
    t341 = (0.5)*t239
    t342 = (0.5)*t240
    t343 = t120*t241 + t316*t36
    t344 = t120*t242 + t317*t36
    t345 = t120*t243 + t318*t36
    t346 = t120*t244 + t319*t36
    t347 = t120*t245 + t320*t36
    t348 = t120*t246 + t321*t36
    t349 = a29*t285 + a32*t293
    t350 = a26*t277 + a32*t294
    t351 = a26*t278 + a29*t286
    t352 = a26*t279 + a29*t287 + a32*t295
    t353 = a26*t280 + a29*t288 + a32*t296
    t354 = a26*t281 + a29*t289 + a32*t297
    t355 = a26*t282 + a29*t290 + a32*t298
    t356 = a26*t283 + a29*t291 + a32*t299
    t357 = a26*t284 + a29*t292 + a32*t300
    t358 = (0.5)*t229
    t359 = (0.5)*t230
    t360 = (0.5)*t231
    t361 = (0.5)*t232
    t362 = (0.5)*t233
    t363 = (0.5)*t234
    t364 = t116*t241 + t117*t235 + t271*t81
    t365 = t116*t242 + t117*t236 + t272*t81
    t366 = t116*t243 + t117*t237 + t273*t81
    t367 = t116*t244 + t117*t238 + t274*t81
    t368 = t116*t245 + t117*t239 + t275*t81
    t369 = t116*t246 + t117*t240 + t276*t81
    out = numpy.zeros((78, x.shape[1]), dtype=x.dtype)
    out[0] = t38
    out[1] = t40
    out[2] = t36
    out[3] = t118*t139 + t122*t142 + t125*t145
    out[4] = t126*t139 + t128*t142 + t131*t145
    out[5] = t132*t139 + t133*t142 + t135*t145
    out[6] = t229
    out[7] = t230
    out[8] = t231
    out[12] = t235
    out[13] = t236
    out[14] = t237
    out[18] = t241
    out[19] = t242
    out[20] = t243
    out[24] = t118*t301 + t122*t328 + t125*t349 - t140*t271 - t141*t259 + t142*t310 + t142*t322 - t145*t337 + t145*t343
    out[25] = t118*t302 + t122*t329 + t125*t350 - t140*t272 - t141*t260 + t142*t311 + t142*t323 - t145*t338 + t145*t344
    out[26] = t118*t303 + t122*t330 + t125*t351 - t140*t273 - t141*t261 + t142*t312 + t142*t324 - t145*t339 + t145*t345
    out[27] = t118*t304 + t122*t331 + t125*t352
    out[28] = t118*t305 + t122*t332 + t125*t353
    out[29] = t118*t306 + t122*t333 + t125*t354
    out[30] = t126*t301 + t128*t328 + t131*t349 - t139*t310 + t139*t322 + t143*t271 - t144*t253 - t144*t265 + t145*t358 + t145*t364
    out[31] = t126*t302 + t128*t329 + t131*t350 - t139*t311 + t139*t323 + t143*t272 - t144*t254 - t144*t266 + t145*t359 + t145*t365
    out[32] = t126*t303 + t128*t330 + t131*t351 - t139*t312 + t139*t324 + t143*t273 - t144*t255 - t144*t267 + t145*t360 + t145*t366
    out[33] = t126*t304 + t128*t331 + t131*t352
    out[34] = t126*t305 + t128*t332 + t131*t353
    out[35] = t126*t306 + t128*t333 + t131*t354
    out[36] = t132*t301 + t133*t328 + t135*t349 + t139*t337 + t139*t343 - t142*t358 + t142*t364 + t146*t271 - t147*t247 - t147*t265
    out[37] = t132*t302 + t133*t329 + t135*t350 + t139*t338 + t139*t344 - t142*t359 + t142*t365 + t146*t272 - t147*t248 - t147*t266
    out[38] = t132*t303 + t133*t330 + t135*t351 + t139*t339 + t139*t345 - t142*t360 + t142*t366 + t146*t273 - t147*t249 - t147*t267
    out[39] = t132*t304 + t133*t331 + t135*t352
    out[40] = t132*t305 + t133*t332 + t135*t353
    out[41] = t132*t306 + t133*t333 + t135*t354
    out[42] = t232
    out[43] = t233
    out[44] = t234
    out[48] = t238
    out[49] = t239
    out[50] = t240
    out[54] = t244
    out[55] = t245
    out[56] = t246
    out[60] = -t140*t274 - t141*t262 + t142*t313 + t142*t325 - t145*t340 + t145*t346
    out[61] = -t140*t275 - t141*t263 + t142*t314 + t142*t326 - t145*t341 + t145*t347
    out[62] = -t140*t276 - t141*t264 + t142*t315 + t142*t327 - t145*t342 + t145*t348
    out[63] = t118*t307 + t122*t334 + t125*t355
    out[64] = t118*t308 + t122*t335 + t125*t356
    out[65] = t118*t309 + t122*t336 + t125*t357
    out[66] = -t139*t313 + t139*t325 + t143*t274 - t144*t256 - t144*t268 + t145*t361 + t145*t367
    out[67] = -t139*t314 + t139*t326 + t143*t275 - t144*t257 - t144*t269 + t145*t362 + t145*t368
    out[68] = -t139*t315 + t139*t327 + t143*t276 - t144*t258 - t144*t270 + t145*t363 + t145*t369
    out[69] = t126*t307 + t128*t334 + t131*t355
    out[70] = t126*t308 + t128*t335 + t131*t356
    out[71] = t126*t309 + t128*t336 + t131*t357
    out[72] = t139*t340 + t139*t346 - t142*t361 + t142*t367 + t146*t274 - t147*t250 - t147*t268
    out[73] = t139*t341 + t139*t347 - t142*t362 + t142*t368 + t146*t275 - t147*t251 - t147*t269
    out[74] = t139*t342 + t139*t348 - t142*t363 + t142*t369 + t146*t276 - t147*t252 - t147*t270
    out[75] = t132*t307 + t133*t334 + t135*t355
    out[76] = t132*t308 + t133*t335 + t135*t356
    out[77] = t132*t309 + t133*t336 + t135*t357
    return out


def cost_0(x):
    """Block type 0 (BetweenFactorPose3), error + cost mode: each member's ½‖W r‖²;
    76 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    a18 = x[18]
    a19 = x[19]
    a20 = x[20]
    a21 = x[21]
    a22 = x[22]
    a23 = x[23]
    a24 = x[24]
    a25 = x[25]
    a26 = x[26]
    a27 = x[27]
    a28 = x[28]
    a29 = x[29]
    a30 = x[30]
    a31 = x[31]
    a32 = x[32]
    a33 = x[33]
    a34 = x[34]
    a35 = x[35]
    a36 = x[36]
    t0 = a0*a12 + a15*a3 + a18*a6
    t1 = t0
    t2 = a1*a12 + a15*a4 + a18*a7
    t3 = t2
    t4 = a12*a2 + a15*a5 + a18*a8
    t5 = t4
    t6 = a24*t1 + a27*t3 + a30*t5
    t7 = a0*a13 + a16*a3 + a19*a6
    t8 = t7
    t9 = a1*a13 + a16*a4 + a19*a7
    t10 = t9
    t11 = a13*a2 + a16*a5 + a19*a8
    t12 = t11
    t13 = a24*t8 + a27*t10 + a30*t12
    t14 = a0*a14 + a17*a3 + a20*a6
    t15 = t14
    t16 = a1*a14 + a17*a4 + a20*a7
    t17 = t16
    t18 = a14*a2 + a17*a5 + a20*a8
    t19 = t18
    t20 = a24*t15 + a27*t17 + a30*t19
    t21 = a25*t1 + a28*t3 + a31*t5
    t22 = a25*t8 + a28*t10 + a31*t12
    t23 = a25*t15 + a28*t17 + a31*t19
    t24 = a26*t1 + a29*t3 + a32*t5
    t25 = a26*t8 + a29*t10 + a32*t12
    t26 = a26*t15 + a29*t17 + a32*t19
    w0_0, w0_1, w0_2 = so3_log(t6, t13, t20, t21, t22, t23, t24, t25, t26)
    t27 = w0_0
    t28 = t27**2
    t29 = w0_1
    t30 = t29**2
    t31 = w0_2
    t32 = t31**2
    t33 = t30
    t34 = t33
    t35 = t32
    t36 = t35
    t37 = t34 + t36
    t38 = t28
    t39 = t38
    t40 = t37 + t39
    t41 = lie_D(t40)
    t42 = -t37*t41 + 1
    t43 = (0.5)*t31
    t44 = t43
    t45 = t27*t41
    t46 = t29*t45
    t47 = t44 + t46
    t48 = (0.5)*t29
    t49 = t48
    t50 = t31*t45
    t51 = -t49 + t50
    t52 = a0*a21 - a0*a9 - a10*a3 - a11*a6 + a22*a3 + a23*a6
    t53 = a1*a21 - a1*a9 - a10*a4 - a11*a7 + a22*a4 + a23*a7
    t54 = -a10*a5 - a11*a8 + a2*a21 - a2*a9 + a22*a5 + a23*a8
    t55 = -a24*a33 + a24*t52 - a27*a34 + a27*t53 - a30*a35 + a30*t54
    t56 = -a25*a33 + a25*t52 - a28*a34 + a28*t53 - a31*a35 + a31*t54
    t57 = -a26*a33 + a26*t52 - a29*a34 + a29*t53 - a32*a35 + a32*t54
    t58 = t42*t55 + t47*t56 + t51*t57
    t59 = -t44 + t46
    t60 = -t36 - t39
    t61 = t41*t60 + 1
    t62 = (0.5)*t27
    t63 = t62
    t64 = t29*t31
    t65 = t41*t64
    t66 = t63 + t65
    t67 = t55*t59 + t56*t61 + t57*t66
    t68 = t49 + t50
    t69 = -t63 + t65
    t70 = -t34 - t39
    t71 = t41*t70 + 1
    t72 = t55*t68 + t56*t69 + t57*t71
    t73 = (0.5)*a36**2
    t74 = t28*t73 + t30*t73 + t32*t73 + t58**2*t73 + t67**2*t73 + t72**2*t73
    out = numpy.zeros((1, x.shape[1]), dtype=x.dtype)
    out[0] = t74
    return out


def jacobian_1(x):
    """Block type 1 (PriorFactorPose3), error + Jacobian mode: residual (6) then
    each variable's Jacobian, row-major; 184 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    a18 = x[18]
    a19 = x[19]
    a20 = x[20]
    a21 = x[21]
    a22 = x[22]
    a23 = x[23]
    t0 = a0*a12 + a15*a3 + a18*a6
    t1 = a12*a2 + a15*a5 + a18*a8
    t2 = a1*a12 + a15*a4 + a18*a7
    t3 = a0*a13 + a16*a3 + a19*a6
    t4 = a13*a2 + a16*a5 + a19*a8
    t5 = a1*a13 + a16*a4 + a19*a7
    t6 = a0*a14 + a17*a3 + a20*a6
    t7 = a14*a2 + a17*a5 + a20*a8
    t8 = a1*a14 + a17*a4 + a20*a7
    t9 = t0
    t10 = t2
    t11 = t1
    t12 = t3
    t13 = t5
    t14 = t4
    t15 = t6
    t16 = t8
    t17 = t7
    w0_0, w0_1, w0_2 = so3_log(t9, t10, t11, t12, t13, t14, t15, t16, t17)
    t18 = w0_2
    t19 = (0.5)*t18
    t20 = w0_0
    t21 = t20**2
    t22 = w0_1
    t23 = t22**2
    t24 = t18**2
    t25 = t23 + t24
    t26 = lie_D(t21 + t25)
    t27 = t20*t26
    t28 = t22*t27
    t29 = -0.5*t19 + (0.5)*t28
    t30 = -t25*t26 + 1
    t31 = (0.5)*t30
    t32 = t12*t29 - t13*t31
    t33 = (0.5)*t22
    t34 = (0.5)*t18*t27 + (0.5)*t33
    t35 = -t15*t34 + (0.5)*t17*t30
    t36 = t15*t29 - t16*t31
    t37 = (0.5)*t11*t30 - t34*t9
    t38 = -t10*t31 + t29*t9
    t39 = -t12*t34 + (0.5)*t14*t30
    t40 = t10*t34 - t11*t29
    t41 = t16*t34 - t17*t29
    t42 = t13*t34 - t14*t29
    t43 = (0.5)*t26*(-t21 - t24) + 0.5
    t44 = t19 + t28
    t45 = (0.5)*t44
    t46 = t12*t43 - t13*t45
    t47 = (0.5)*t20
    t48 = t18*t22
    t49 = t26*t48
    t50 = -0.5*t47 + (0.5)*t49
    t51 = -t15*t50 + (0.5)*t17*t44
    t52 = t15*t43 - t16*t45
    t53 = (0.5)*t11*t44 - t50*t9
    t54 = -t10*t45 + t43*t9
    t55 = -t12*t50 + (0.5)*t14*t44
    t56 = t10*t50 - t11*t43
    t57 = t16*t50 - t17*t43
    t58 = t13*t50 - t14*t43
    t59 = (0.5)*t47 + (0.5)*t49
    t60 = t18*t20*t26 - t33
    t61 = (0.5)*t60
    t62 = t12*t59 - t13*t61
    t63 = (0.5)*t26*(-t21 - t23) + 0.5
    t64 = -t15*t63 + (0.5)*t17*t60
    t65 = t15*t59 - t16*t61
    t66 = (0.5)*t11*t60 - t63*t9
    t67 = -t10*t61 + t59*t9
    t68 = -t12*t63 + (0.5)*t14*t60
    t69 = t10*t63 - t11*t59
    t70 = t16*t63 - t17*t59
    t71 = t13*t63 - t14*t59
    t72 = 2*t22
    t73 = 2*t18
    t74 = 2*t20
    t75 = t23
    t76 = t24
    t77 = t75 + t76
    t78 = t21
    t79 = t77 + t78
    t80 = lie_D1(t79)
    t81 = lie_D(t79)
    t82 = t22*t81
    t83 = t18*t81
    t84 = -t77*t81 + 1
    t85 = t19
    t86 = t20*t81
    t87 = t22*t86
    t88 = t85 + t87
    t89 = t33
    t90 = t18*t86
    t91 = -t89 + t90
    t92 = -t85 + t87
    t93 = -t76 - t78
    t94 = t81*t93 + 1
    t95 = t47
    t96 = t48*t81
    t97 = t95 + t96
    t98 = t89 + t90
    t99 = -t95 + t96
    t100 = -t75 - t78
    t101 = t100*t81 + 1
    t102 = a10*a15 + a11*a18 - a12*a21 + a12*a9 - a15*a22 - a18*a23
    t103 = t102*t77
    t104 = t102*t81
    t105 = a10*a16 + a11*a19 - a13*a21 + a13*a9 - a16*a22 - a19*a23
    t106 = t105*t93
    t107 = t105*t81
    t108 = a10*a17 + a11*a20 - a14*a21 + a14*a9 - a17*a22 - a20*a23
    t109 = t100*t108
    t110 = t108*t81
    t111 = -t1
    t112 = t2
    t113 = t1
    t114 = -t0
    t115 = -t2
    t116 = t0
    t117 = -t4
    t118 = t5
    t119 = t4
    t120 = -t3
    t121 = -t5
    t122 = t3
    t123 = -t7
    t124 = t8
    t125 = t7
    t126 = -t6
    t127 = -t8
    t128 = t6
    t129 = t113*t37 + t115*t38 + t119*t39 + t121*t32 + t125*t35 + t127*t36
    t130 = t111*t40 + t116*t38 + t117*t42 + t122*t32 + t123*t41 + t128*t36
    t131 = t112*t40 + t114*t37 + t118*t42 + t120*t39 + t124*t41 + t126*t35
    t132 = t113*t53 + t115*t54 + t119*t55 + t121*t46 + t125*t51 + t127*t52
    t133 = t111*t56 + t116*t54 + t117*t58 + t122*t46 + t123*t57 + t128*t52
    t134 = t112*t56 + t114*t53 + t118*t58 + t120*t55 + t124*t57 + t126*t51
    t135 = t113*t66 + t115*t67 + t119*t68 + t121*t62 + t125*t64 + t127*t65
    t136 = t111*t69 + t116*t67 + t117*t71 + t122*t62 + t123*t70 + t128*t65
    t137 = t112*t69 + t114*t66 + t118*t71 + t120*t68 + t124*t70 + t126*t64
    t138 = t132*t72
    t139 = t133*t72
    t140 = t134*t72
    t141 = t135*t73
    t142 = t136*t73
    t143 = t137*t73
    t144 = t138 + t141
    t145 = t139 + t142
    t146 = t140 + t143
    t147 = t129*t74
    t148 = t130*t74
    t149 = t131*t74
    t150 = t144*t80 + t147*t80
    t151 = t145*t80 + t148*t80
    t152 = t146*t80 + t149*t80
    t153 = t0
    t154 = t2
    t155 = t1
    t156 = (0.5)*t135
    t157 = (0.5)*t136
    t158 = (0.5)*t137
    t159 = t129*t81 + t150*t20
    t160 = t130*t81 + t151*t20
    t161 = t131*t81 + t152*t20
    t162 = t132*t86 + t159*t22
    t163 = t133*t86 + t160*t22
    t164 = t134*t86 + t161*t22
    t165 = t3
    t166 = t5
    t167 = t4
    t168 = (0.5)*t132
    t169 = (0.5)*t133
    t170 = (0.5)*t134
    t171 = t135*t86 + t159*t18
    t172 = t136*t86 + t160*t18
    t173 = t137*t86 + t161*t18
    t174 = t6
    t175 = t8
    t176 = t7
    t177 = (0.5)*t129
    t178 = (0.5)*t130
    t179 = (0.5)*t131
    t180 = t132*t83 + t135*t82 + t150*t48
    t181 = t133*t83 + t136*t82 + t151*t48
    t182 = t134*t83 + t137*t82 + t152*t48
    out = numpy.zeros((42, x.shape[1]), dtype=x.dtype)
    out[0] = t20
    out[1] = t22
    out[2] = t18
    out[3] = t102*t84 + t105*t88 + t108*t91
    out[4] = t102*t92 + t105*t94 + t108*t97
    out[5] = t101*t108 + t102*t98 + t105*t99
    out[6] = t129
    out[7] = t130
    out[8] = t131
    out[12] = t132
    out[13] = t133
    out[14] = t134
    out[18] = t135
    out[19] = t136
    out[20] = t137
    out[24] = -t103*t150 - t104*t144 + t105*t156 + t105*t162 - t108*t168 + t108*t171
    out[25] = -t103*t151 - t104*t145 + t105*t157 + t105*t163 - t108*t169 + t108*t172
    out[26] = -t103*t152 - t104*t146 + t105*t158 + t105*t164 - t108*t170 + t108*t173
    out[27] = t153*t84 + t165*t88 + t174*t91
    out[28] = t154*t84 + t166*t88 + t175*t91
    out[29] = t155*t84 + t167*t88 + t176*t91
    out[30] = -t102*t156 + t102*t162 + t106*t150 - t107*t141 - t107*t147 + t108*t177 + t108*t180
    out[31] = -t102*t157 + t102*t163 + t106*t151 - t107*t142 - t107*t148 + t108*t178 + t108*t181
    out[32] = -t102*t158 + t102*t164 + t106*t152 - t107*t143 - t107*t149 + t108*t179 + t108*t182
    out[33] = t153*t92 + t165*t94 + t174*t97
    out[34] = t154*t92 + t166*t94 + t175*t97
    out[35] = t155*t92 + t167*t94 + t176*t97
    out[36] = t102*t168 + t102*t171 - t105*t177 + t105*t180 + t109*t150 - t110*t138 - t110*t147
    out[37] = t102*t169 + t102*t172 - t105*t178 + t105*t181 + t109*t151 - t110*t139 - t110*t148
    out[38] = t102*t170 + t102*t173 - t105*t179 + t105*t182 + t109*t152 - t110*t140 - t110*t149
    out[39] = t101*t174 + t153*t98 + t165*t99
    out[40] = t101*t175 + t154*t98 + t166*t99
    out[41] = t101*t176 + t155*t98 + t167*t99
    return out


def cost_1(x):
    """Block type 1 (PriorFactorPose3), error + cost mode: each member's ½‖W r‖²;
    64 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    a18 = x[18]
    a19 = x[19]
    a20 = x[20]
    a21 = x[21]
    a22 = x[22]
    a23 = x[23]
    a24 = x[24]
    t0 = a0*a12 + a15*a3 + a18*a6
    t1 = t0
    t2 = a1*a12 + a15*a4 + a18*a7
    t3 = t2
    t4 = a12*a2 + a15*a5 + a18*a8
    t5 = t4
    t6 = a0*a13 + a16*a3 + a19*a6
    t7 = t6
    t8 = a1*a13 + a16*a4 + a19*a7
    t9 = t8
    t10 = a13*a2 + a16*a5 + a19*a8
    t11 = t10
    t12 = a0*a14 + a17*a3 + a20*a6
    t13 = t12
    t14 = a1*a14 + a17*a4 + a20*a7
    t15 = t14
    t16 = a14*a2 + a17*a5 + a20*a8
    t17 = t16
    w0_0, w0_1, w0_2 = so3_log(t1, t3, t5, t7, t9, t11, t13, t15, t17)
    t18 = w0_0
    t19 = t18**2
    t20 = w0_1
    t21 = t20**2
    t22 = w0_2
    t23 = t22**2
    t24 = t21
    t25 = t24
    t26 = t23
    t27 = t26
    t28 = t25 + t27
    t29 = t19
    t30 = t29
    t31 = t28 + t30
    t32 = lie_D(t31)
    t33 = -t28*t32 + 1
    t34 = (0.5)*t22
    t35 = t34
    t36 = t18*t32
    t37 = t20*t36
    t38 = t35 + t37
    t39 = (0.5)*t20
    t40 = t39
    t41 = t22*t36
    t42 = -t40 + t41
    t43 = a10*a15 + a11*a18 - a12*a21 + a12*a9 - a15*a22 - a18*a23
    t44 = a10*a16 + a11*a19 - a13*a21 + a13*a9 - a16*a22 - a19*a23
    t45 = a10*a17 + a11*a20 - a14*a21 + a14*a9 - a17*a22 - a20*a23
    t46 = t33*t43 + t38*t44 + t42*t45
    t47 = -t35 + t37
    t48 = -t27 - t30
    t49 = t32*t48 + 1
    t50 = (0.5)*t18
    t51 = t50
    t52 = t20*t22
    t53 = t32*t52
    t54 = t51 + t53
    t55 = t43*t47 + t44*t49 + t45*t54
    t56 = t40 + t41
    t57 = -t51 + t53
    t58 = -t25 - t30
    t59 = t32*t58 + 1
    t60 = t43*t56 + t44*t57 + t45*t59
    t61 = (0.5)*a24**2
    t62 = t19*t61 + t21*t61 + t23*t61 + t46**2*t61 + t55**2*t61 + t60**2*t61
    out = numpy.zeros((1, x.shape[1]), dtype=x.dtype)
    out[0] = t62
    return out


# --------------------------------------------------------------------------------------------
# variable types: x ∘ Exp(δ) and Log(a⁻¹ b), printed from fgc.frontend.geometry; x is
# (inputs × instances), out is (outputs × instances)
# --------------------------------------------------------------------------------------------


def retract_0(x):
    """Variable type 0 (Pose3): inputs storage (12) then δ (6), outputs the
    storage of x ∘ Exp(δ); 34 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    t0 = a13**2
    t1 = a14**2
    t2 = t0 + t1
    t3 = -t2
    t4 = a12**2
    t5 = t2 + t4
    t6 = lie_B(t5)
    t7 = t3*t6 + 1
    t8 = lie_A(t5)
    t9 = a14*t8
    t10 = a13*t6
    t11 = a12*t10
    t12 = t11 + t9
    t13 = a13*t8
    t14 = a14*t6
    t15 = a12*t14
    t16 = -t13 + t15
    t17 = t11 - t9
    t18 = -t1 - t4
    t19 = t18*t6 + 1
    t20 = a12*t8
    t21 = a13*t14 + t20
    t22 = t13 + t15
    t23 = a13*a14*t6 - t20
    t24 = -t0 - t4
    t25 = t24*t6 + 1
    t26 = lie_C(t5)
    t27 = a12*t26
    t28 = a13*t27
    t29 = a14*t27
    t30 = a15*(t26*t3 + 1) + a16*(-t14 + t28) + a17*(t10 + t29)
    t31 = a12*t6
    t32 = a15*(t14 + t28) + a16*(t18*t26 + 1) + a17*(a13*a14*t26 - t31)
    t33 = a15*(-t10 + t29) + a16*(a13*a14*t26 + t31) + a17*(t24*t26 + 1)
    out = numpy.zeros((12, x.shape[1]), dtype=x.dtype)
    out[0] = a0*t7 + a1*t12 + a2*t16
    out[1] = a0*t17 + a1*t19 + a2*t21
    out[2] = a0*t22 + a1*t23 + a2*t25
    out[3] = a3*t7 + a4*t12 + a5*t16
    out[4] = a3*t17 + a4*t19 + a5*t21
    out[5] = a3*t22 + a4*t23 + a5*t25
    out[6] = a6*t7 + a7*t12 + a8*t16
    out[7] = a6*t17 + a7*t19 + a8*t21
    out[8] = a6*t22 + a7*t23 + a8*t25
    out[9] = a0*t30 + a1*t32 + a2*t33 + a9
    out[10] = a10 + a3*t30 + a4*t32 + a5*t33
    out[11] = a11 + a6*t30 + a7*t32 + a8*t33
    return out


def local_0(x):
    """Variable type 0 (Pose3): inputs the storage of a then of b (12 each), outputs
    Log(a⁻¹ b) (6); 28 assignments."""
    a0 = x[0]
    a1 = x[1]
    a2 = x[2]
    a3 = x[3]
    a4 = x[4]
    a5 = x[5]
    a6 = x[6]
    a7 = x[7]
    a8 = x[8]
    a9 = x[9]
    a10 = x[10]
    a11 = x[11]
    a12 = x[12]
    a13 = x[13]
    a14 = x[14]
    a15 = x[15]
    a16 = x[16]
    a17 = x[17]
    a18 = x[18]
    a19 = x[19]
    a20 = x[20]
    a21 = x[21]
    a22 = x[22]
    a23 = x[23]
    t0 = a0*a12 + a15*a3 + a18*a6
    t1 = a0*a13 + a16*a3 + a19*a6
    t2 = a0*a14 + a17*a3 + a20*a6
    t3 = a1*a12 + a15*a4 + a18*a7
    t4 = a1*a13 + a16*a4 + a19*a7
    t5 = a1*a14 + a17*a4 + a20*a7
    t6 = a12*a2 + a15*a5 + a18*a8
    t7 = a13*a2 + a16*a5 + a19*a8
    t8 = a14*a2 + a17*a5 + a20*a8
    w0_0, w0_1, w0_2 = so3_log(t0, t1, t2, t3, t4, t5, t6, t7, t8)
    t9 = w0_0
    t10 = w0_1
    t11 = w0_2
    t12 = t10**2
    t13 = t11**2
    t14 = t12 + t13
    t15 = t9**2
    t16 = lie_D(t14 + t15)
    t17 = a0*a21 - a0*a9 - a10*a3 - a11*a6 + a22*a3 + a23*a6
    t18 = (0.5)*t11
    t19 = t16*t9
    t20 = t10*t19
    t21 = a1*a21 - a1*a9 - a10*a4 - a11*a7 + a22*a4 + a23*a7
    t22 = (0.5)*t10
    t23 = t11*t19
    t24 = -a10*a5 - a11*a8 + a2*a21 - a2*a9 + a22*a5 + a23*a8
    t25 = (0.5)*t9
    t26 = t10*t11*t16
    out = numpy.zeros((6, x.shape[1]), dtype=x.dtype)
    out[0] = t9
    out[1] = t10
    out[2] = t11
    out[3] = t17*(-t14*t16 + 1) + t21*(t18 + t20) + t24*(-t22 + t23)
    out[4] = t17*(-t18 + t20) + t21*(t16*(-t13 - t15) + 1) + t24*(t25 + t26)
    out[5] = t17*(t22 + t23) + t21*(-t25 + t26) + t24*(t16*(-t12 - t15) + 1)
    return out


# --------------------------------------------------------------------------------------------
# structure tables (variables by index, in the Program's order)
# --------------------------------------------------------------------------------------------

BLOCKS = (
    {  # block type 0: BetweenFactorPose3
        "jacobian": jacobian_0,
        "cost": cost_0,
        "residual_dim": 6,
        "variable_dims": (6, 6),
        "variable_storage": (12, 12),
        # (first row, last row, noise kind, noise parameters, measurement numbers, variables)
        "members": ((0, 6, 0, 1, 12, (0, 1)),),
        "instances": ((0, 1), (1, 2), (2, 3), (3, 4), (1, 4), (3, 0)),
        "factor_ids": (0, 1, 2, 3, 4, 5),
    },
    {  # block type 1: PriorFactorPose3
        "jacobian": jacobian_1,
        "cost": cost_1,
        "residual_dim": 6,
        "variable_dims": (6,),
        "variable_storage": (12,),
        # (first row, last row, noise kind, noise parameters, measurement numbers, variables)
        "members": ((0, 6, 0, 1, 12, (0,)),),
        "instances": ((0,),),
        "factor_ids": (6,),
    },
)

PROBLEM = {
    # the data files this simulator reads must carry this structure fingerprint (the design's
    # fingerprint is left out: one simulator serves every unit count of a design)
    "structure": "f9f74f37094aaf64",
    "solver": {
        "method": 'lm',
        "linear": 'qr',
        "precision": 'float32',
        "linear_precision": None,
        "max_iterations": 100,
        "lambda_initial": 1e-05,
        "lambda_factor": 10.0,
        "lambda_upper_bound": 10000000000.0,
        "mu_min": 1e-30,
        "eps_gradient": 1e-12,
        "eps_step": 1e-12,
        "relative_error_tol": 1e-12,
        "absolute_error_tol": 1e-14,
        "diagnose": True,
        "condition_iterations": 12,
        "singular_lm_fails": False,
        "pivot_tolerance_float64": 1e-10,
        "pivot_tolerance_float32": 1e-05,
    },
    "num_factors": 7,
    "variable_dims": (6, 6, 6, 6, 6),
    "variable_storage": (12, 12, 12, 12, 12),
    # per variable: its key as JSON text, "hex:" + hex digits if not plain (the user's key, an
    # int stays an int; decoded, never run) and its value type; results are keyed by it
    "variables": (
        ('"x0"', 'Pose3'),
        ('"x1"', 'Pose3'),
        ('"x2"', 'Pose3'),
        ('"x3"', 'Pose3'),
        ('"x4"', 'Pose3'),
    ),
    # per variable type: (retraction, local coordinates); variables by type
    "types": (
        (retract_0, local_0),  # Pose3
    ),
    "retract_groups": ((0, (0, 1, 2, 3, 4)),),
    "blocks": BLOCKS,
    # (frontals, separator, entering factors as (block type, instance, member), children, parent)
    "steps": (
        ((0,), (1, 3), ((0, 0, 0), (0, 5, 0), (1, 0, 0)), (), 2),
        ((2,), (1, 3), ((0, 1, 0), (0, 2, 0)), (), 2),
        ((1, 3, 4), (), ((0, 3, 0), (0, 4, 0)), (0, 1), -1),
    ),
    "back_substitution": ((2,), (0, 1)),
    # chain clusters (variables per keyframe) and the incremental plan: per arriving keyframe
    # (keyframe, batch step?, clusters re-eliminated, clusters kept)
    "clusters": None,
    "incremental": None,
}


def run(data_path, result_path=None, precision=None, policy=None, progress=None):
    """Solve the problem in ``data_path``; see fgc_sim_optimizer.solve."""
    return LIB.optimizer.solve(PROBLEM, data_path, result_path, precision, LIB, policy,
                               progress)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data", help="fgc data file")
    parser.add_argument("result", help="JSON result file to write")
    parser.add_argument("--precision", choices=("float32", "float64"), default=None)
    parser.add_argument("--incremental", action="store_true",
                        help="keyframe by keyframe, following the compiled incremental plan")
    parser.add_argument("--window", type=int, metavar="W",
                        help="keyframe by keyframe in a fixed-lag window of W keyframes, the "
                             "keyframe leaving marginalised into a prior on the window")
    parser.add_argument("--policy", type=json.loads, metavar="JSON",
                        help="the streaming policy as a JSON object (what fgc passes: "
                             '{"mode": "fixed-lag", "window": W} or {"mode": "incremental"})')
    args = parser.parse_args(argv)
    policy = args.policy
    if args.incremental:
        policy = {"mode": "incremental"}
    elif args.window is not None:
        policy = {"mode": "fixed-lag", "window": args.window}
    try:
        result = run(args.data, args.result, args.precision, policy)
    except LIB.runtime.SimDataError as exc:
        LIB.optimizer.write_error(args.result, exc)
        print(f"{os.path.basename(__file__)}: error: {exc}", file=sys.stderr)
        return 2
    print(f"{result['status']} ({result['reason']}): {result['iterations']} iterations, "
          f"error {result['initial_error']} -> {result['final_error']}")
    return 0 if result["converged"] else 1


if __name__ == "__main__":
    sys.exit(main())
