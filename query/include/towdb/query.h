/*
 * towdb/query.h -- the towdb query library: extreme towline tension for tow
 * planners, interpolated from a towdb database. This header is the whole API
 * ("if it isn't here, it isn't API"); towdb/query.hpp is a thin C++ wrapper.
 *
 * ---------------------------------------------------------------------------
 * WHAT IS COMPUTED
 *
 * A towdb database holds towing cases (tug, tow, towline, sea, speed, heading,
 * towline length, mean tension) and for each the Type I (Gumbel) distribution
 * of the daily maximum dynamic tension (schema/README.md, table `results`).
 *
 * EQ-QUERY-1  Gumbel (Type I) law of the daily maximum dynamic tension X:
 *               F(x) = exp(-exp(-alpha (x - u))),   beta = 1/alpha.
 * EQ-QUERY-2  Maximum over a tow of D days (independent days):
 *               F_D(x) = F(x)^D  =>  u_D = u + beta ln(D),  same beta.
 * EQ-QUERY-3  Dynamic tension exceeded with probability p by the maximum of
 *             the tow (p per day when D = 1; the database value is p = 0.001):
 *               x(p, D) = u_D - beta ln(-ln(1 - p)).
 * EQ-QUERY-4  Extreme tension = mean tension + x(p, D)   (thesis ch. 1, 6).
 * EQ-QUERY-5  U.S. Navy Towing Manual checks with breaking strength BS:
 *               extreme tension <= BS / 1.5;
 *               mean tension <= BS / 3 (automatic towing machine),
 *               mean tension <= BS / 5 (towline held on the brake).
 * EQ-QUERY-6  Interpolation. Categorical: tug, tow, line type (and the sea
 *             spectrum family). Continuous grid axes, each the sorted set of
 *             distinct stored values: speed_kt, sea (wind_kt for a
 *             Pierson-Moskowitz sea, else hs_ft), tp_s (two-parameter seas
 *             only), heading_deg folded to [0, 180] by port/starboard symmetry
 *             (h > 180 -> 360 - h), length_ft. Multilinear weights over the
 *             2^k corners of the cell that holds the query:
 *               w_c = prod_a ((1 - t_a) or t_a),  t_a = (q_a - x_i)/(x_{i+1} - x_i).
 *             Mean tension is NOT a grid axis: each grid node has its own 1-4
 *             stored mean tensions m_1 < ... < m_n, and the node's parameters
 *             are interpolated in m at the query's mean tension before the
 *             corners are combined (at m itself, or at f T_calc,c on the
 *             relative axis of EQ-QUERY-9): with n >= 3 by the monotone
 *             piecewise-cubic Hermite interpolant (Fritsch & Carlson 1980;
 *             slopes: the weighted harmonic mean of the neighbouring
 *             secants, 0 at a local extremum, the end secant at an end;
 *             Fritsch & Butland 1984), with n = 2 linearly. It passes through
 *             the stored values, is exact for data linear in m, and never
 *             overshoots where the data are monotone (the rise of the tension
 *             where a slack line starts to snatch); measured against direct
 *             simulations it lowers the 90th-percentile error (docs/audit.md).
 *             The catenary's and the slack's quantities stay linear in m.
 *             Interpolated quantities: g = u and g = beta, either as
 *               linear space: g = sum_c w_c g_c, or
 *               log space:    g = exp(sum_c w_c ln g_c);
 *             the stored confidence interval's bounds in the same space (in
 *             log space linear where a bound is <= 0), so that it brackets
 *             the answer as the corners' intervals bracket theirs.
 *             The space is chosen when the database is opened, by the
 *             leave-one-out test of EQ-QUERY-8 (smaller 90th-percentile error
 *             wins; linear on a tie, and linear whenever some stored u <= 0).
 *             Result: in linear space x(p, D) = sum_c w_c x_c(p, D), so the
 *             answer is monotone along an axis whenever the corner values are
 *             (checked: a warning when more wind or less towline length would
 *             lower the answer inside the query's cell).
 * EQ-QUERY-7  Interpolation error estimate along axis a (linear interpolation
 *             of a function with second derivative f''):
 *               e_a = t_a (1 - t_a) h_a^2 |f''| / 2,
 *             f''/2 taken as the second divided difference of x(p, D) over
 *             the cell's two nodes and the next node outside the cell (the
 *             larger of the two sides where both exist). Along an axis (or a
 *             node's mean tensions) with only the cell's two values, or where
 *             no node beside the cell can be evaluated at the question (not
 *             stored, or the mean tension outside the ones it stores), there is
 *             no curvature to measure, and
 *               e_a = t_a (1 - t_a) |f(x_{i+1}) - f(x_i)|,
 *             the error of a chord under a curve that sags by a quarter of its
 *             rise at mid-cell (f ~ x^2 across the cell); on a grid axis with
 *             curvature information e_a is at least half that (the tension
 *             can change abruptly inside a cell, e.g. slack in exactly
 *             following seas only; the factor is calibrated by towdb audit,
 *             docs/audit.md). The estimate is
 *             summed over the axes and the mean tension (there it is the
 *             chord's estimate, on the safe side: the cubic's error is
 *             usually smaller). In log space f = ln x and the estimate is multiplied
 *             by x (dx = x d ln x).
 *             Total uncertainty = sqrt(e^2 + c^2), c the stored confidence
 *             half-width (ci_high - ci_low)/2 of dynamic_999, scaled to
 *             (p, D) by the method-of-moments quantile standard error
 *             s_x ~ sqrt(1 + 1.1396 K + 1.1 K^2),  K = (x - mean)/stdev
 *               = (sqrt 6/pi)(ln D - ln(-ln(1 - p)) - gamma_Euler)
 *             (Gumbel 1958; Kite 1977, "Frequency and Risk Analyses in
 *             Hydrology", ch. 8).
 * EQ-QUERY-8  Leave-one-out error: every stored case that has stored
 *             neighbours on both sides along an axis (or along its node's
 *             mean tensions) is predicted from those two neighbours alone;
 *             relative error |x_pred - x_stored| / x_stored of the 0.001/day
 *             dynamic tension. This is the error at twice the grid spacing
 *             (about 4x the mid-cell error of EQ-QUERY-7 for smooth data).
 *             Along the mean tensions the prediction is the two neighbours'
 *             chord, not EQ-QUERY-6's cubic through the node's other values
 *             (whose own leave-one-out, in docs/audit.md, is usually the
 *             smaller).
 * EQ-QUERY-9  Mean-tension axis. Where every stored case carries the
 *             calculated mean tension T_calc of its own speed, wind and
 *             heading (cases.calculated_mean_tension_lbf, the sweep's
 *             EQ-SWEEP-1), the mean tension is interpolated as the factor
 *             f = m / T_calc, which means the same at every node:
 *               T_calc(q) = exp(sum_c w_c ln T_calc,c)  (the cell's weights),
 *               f = m / T_calc(q)  (f = 1 when no mean tension is given),
 *             and node c is read at f T_calc,c between its stored mean
 *             tensions as EQ-QUERY-6 says. A node refuses an f outside its stored
 *             factors unless extrapolation is asked for. Without stored
 *             T_calc the mean tension is absolute (the same m at every node).
 * EQ-QUERY-10 A sea given as Hs (optionally Tp) where the database holds
 *             fully developed (Pierson-Moskowitz) wind seas only, for that
 *             tug, tow and line: answered at the wind U whose sea has that Hs,
 *               Hs = 0.2092 U^2 / g   (U at 19.5 m; generator EQ-SEA-1),
 *             stated in the answer (equivalent_wind_kt and a warning). A Tp
 *             more than 20 % from that sea's Tp = 2 pi U / (0.877 g) is
 *             refused (TOWDB_QUERY_RANGE) naming both periods.
 * EQ-QUERY-11 Heading profiles. Where the database stores a linear heading
 *             profile sigma_l(h) for the line l of a stored mean tension (the
 *             cases that differ only in heading; heading_profiles, the
 *             generator's EQ-CASE-3 and EQ-SWEEP-8: the linear model's
 *             dynamic-tension standard deviation every 2.5 deg, ln sigma
 *             linear in between), a cell whose heading is not pinned moves
 *             each corner c from its node's heading h_c to the query's h_q
 *             along that profile before the weights of EQ-QUERY-6 combine
 *             them:
 *               g_c <- g_c + k_l (ln sigma_l(h_q) - ln sigma_l(h_c))  (log space),
 *               g_c <- g_c (sigma_l(h_q) / sigma_l(h_c))^k_l           (linear space),
 *             for u, beta and the stored interval alike (a change of scale),
 *             averaged over the node's two mean tensions with their weights
 *             when the corner lies between them. Across a heading cell the
 *             query thus interpolates x / sigma, not x: near beam seas the
 *             tension has minima a few degrees wide, where the first-order
 *             surge force (which turns with cos mu) and the heave/pitch
 *             extension cancel in the line, and the linear model has them
 *             too (docs/audit.md). The exponent k_l says how much deeper
 *             the tension's minima and peaks are than the linear model's
 *             (slack and snatch loads grow faster than sigma): measured on
 *             the line's own stored headings h_j (the cases that share the
 *             profile), as the least-squares slope through the origin of
 *               d_x(j) = ln x(h_j) - chord of ln x between h_(j-1), h_(j+1)
 *             (x the stored x(0.001, 1) of EQ-QUERY-3) against d_s(j), the
 *             same departure of ln sigma_l, over the
 *             interior headings; clamped to [1, 2] (below 1 it would flatten
 *             the profile where additive forces the linear model lacks blur
 *             the tension's shape; above 2 a few headings over-amplify narrow
 *             minima; docs/audit.md), 1 when ln sigma_l has no curvature at
 *             the stored headings. Across a heading cell the query thus
 *             interpolates x / sigma^k: the chord of ln x plus k times the
 *             profile's departure from its own chord. Exact when
 *             x / sigma^k is what EQ-QUERY-6 reproduces exactly (k = 1 when
 *             x / sigma is); unchanged at the stored headings. A cell
 *             with any corner without a profile is interpolated as without
 *             profiles (never half corrected). Along heading the error
 *             estimate of EQ-QUERY-7 then takes its differences of the
 *             stored headings' values each moved to h_q the same way, i.e.
 *             of x / sigma^k: where the profile explains the tension's change
 *             the estimate is small, where the ratio changes (slack, the
 *             slowly varying forces) it is not.
 * EQ-QUERY-12 Speed profiles. The same along speed: where the database
 *             stores a linear speed profile sigma_l(V) for the line l of a
 *             stored case (the cases that differ only in speed and the mean
 *             tension that goes with it; speed_profiles, the generator's
 *             EQ-SWEEP-9: every 0.25 kt at most, the mean tension of the
 *             line's stored cases joined geometrically in speed, which is
 *             f T_calc(q) of EQ-QUERY-9 on a relative axis), a cell whose
 *             speed is not pinned moves each corner from V_c to V_q (with
 *             k = 1: a fitted exponent along speed, from the line's three
 *             stored speeds, made the worst answers worse; docs/audit.md):
 *               g_c <- g_c + ln sigma_l(V_q) - ln sigma_l(V_c)   (log space),
 *             (a factor in linear space), after the heading move of
 *             EQ-QUERY-11 (the two shifts add: a corner goes from (V_c, h_c)
 *             to (V_q, h_q) along its heading profile at V_c, then its speed
 *             profile at h_c). In following and quartering seas the encounter
 *             frequency folds (w_e = g / 4V) through the coupled surge
 *             response within a fraction of a knot and the tension swings
 *             by a factor of 7 between speeds 1.75 kt apart; the linear
 *             model swings with it (docs/audit.md). Never half corrected;
 *             the error estimate along speed differences x / sigma, as along
 *             heading.
 *
 * CONVENTIONS AND UNITS
 *   Units are those of the database, in every name: kt, ft, lbf, kips
 *   (1 kip = 1000 lbf), deg, s. Heading 0 deg = following (trailing) seas,
 *   180 deg = head seas; [0, 360] accepted, folded to [0, 180].
 *   Vessel names match the database's names ignoring case, spaces and
 *   hyphens ("T-ATF 166" = "tatf166"); a unique prefix is enough ("T-ATF").
 *   Out of the stored range the library refuses (TOWDB_QUERY_RANGE) unless
 *   extrapolation is asked for; then it extrapolates linearly from the end
 *   cell (constant along an axis with one stored value) and warns.
 *
 * ERRORS AND OWNERSHIP (after sqlite3)
 *   Every function returns an int code (TOWDB_QUERY_OK = 0). After a failure
 *   towdb_query_errmsg(db) names the field, the value and what is allowed.
 *   Strings returned by the library are owned by the handle and stay valid
 *   until the next call on that handle. towdb_query_close(NULL) is a no-op.
 *   A handle must not be used from two threads at once; separate handles are
 *   independent. No function throws or aborts on bad input.
 *
 * SOURCE: Desroches, A. S. (1997), "Calculation of extreme towline tension
 *   during open ocean towing", MIT thesis, ch. 4 (Type I statistics), 6.1 (limits of the
 *   towline model above breaking strength), Appendix C (the database);
 *   U.S. Navy Towing Manual SL740-AA-MAN-010 (safety factors).
 */
#ifndef TOWDB_QUERY_H
#define TOWDB_QUERY_H

#if defined(_WIN32)
#if defined(TOWDB_QUERY_BUILDING)
#define TOWDB_QUERY_API __declspec(dllexport)
#else
#define TOWDB_QUERY_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define TOWDB_QUERY_API __attribute__((visibility("default")))
#else
#define TOWDB_QUERY_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Result codes. */
#define TOWDB_QUERY_OK 0
#define TOWDB_QUERY_ERROR 1     /* internal error (a bug: please report it) */
#define TOWDB_QUERY_INPUT 2     /* a bad request: NaN, negative length, unknown vessel, p not in (0,1) */
#define TOWDB_QUERY_RANGE 3     /* outside the stored data and extrapolation was not asked for */
#define TOWDB_QUERY_DATABASE 4  /* missing, corrupt, not a towdb database, a schema version from the future,
                                   a stored value no towdb build writes (NaN, inf, alpha <= 0, dynamic_999 not
                                   u + beta y_999, ...: named with its case, table.column and value), or no
                                   finished cases */
#define TOWDB_QUERY_NUMERICAL 5 /* the interpolant is not physical there (e.g. scale <= 0, or a value not finite,
                                   when extrapolating far) */
#define TOWDB_QUERY_MISUSE 6    /* NULL handle or pointer, index out of range */
#define TOWDB_QUERY_NOMEM 7     /* out of memory */

/* Interpolation space of the Gumbel parameters (EQ-QUERY-6). */
#define TOWDB_QUERY_SPACE_AUTO 0   /* chosen by leave-one-out when opening (default) */
#define TOWDB_QUERY_SPACE_LINEAR 1
#define TOWDB_QUERY_SPACE_LOG 2

/* Axes, for the leave-one-out report. */
#define TOWDB_QUERY_AXIS_ALL (-1)
#define TOWDB_QUERY_AXIS_SPEED 0
#define TOWDB_QUERY_AXIS_SEA 1 /* wind_kt or hs_ft */
#define TOWDB_QUERY_AXIS_PERIOD 2
#define TOWDB_QUERY_AXIS_HEADING 3
#define TOWDB_QUERY_AXIS_LENGTH 4
#define TOWDB_QUERY_AXIS_MEAN_TENSION 5
#define TOWDB_QUERY_AXIS_COUNT 6

/* Warning kinds. */
#define TOWDB_QUERY_WARN_EXTRAPOLATED 1       /* outside the stored range on some axis */
#define TOWDB_QUERY_WARN_ABOVE_BREAKING 2     /* towline model invalid above breaking strength (thesis 6.1) */
#define TOWDB_QUERY_WARN_SLACK 3              /* slack-prone: Type I underestimates (thesis 4.2) */
#define TOWDB_QUERY_WARN_NOT_MONOTONE 4       /* the data is not monotone where physics says it should be */
#define TOWDB_QUERY_WARN_INCOMPLETE_GRID 5    /* missing grid nodes were left out (extrapolate only) */
#define TOWDB_QUERY_WARN_HIGH_TENSION 6       /* dynamic tension above 300 kips: reduced accuracy (thesis 6.2) */
#define TOWDB_QUERY_WARN_BREAKING_DIFFERS 7   /* the corner cases disagree on breaking strength */
#define TOWDB_QUERY_WARN_ABOVE_CAPACITY 8     /* mean tension above the tugs' 125,000 lbf (thesis ch. 5) */
#define TOWDB_QUERY_WARN_EQUIVALENT_WIND 9    /* hs_ft answered through the equivalent wind (EQ-QUERY-10) */

typedef struct towdb_query_db towdb_query_db;

/* One query. Initialise with towdb_query_request_init, then set fields. */
typedef struct towdb_query_request {
  const char* tug;          /* tug name (required) */
  const char* tow;          /* tow name (required) */
  const char* line;         /* "wire" or "fiber" (required) */
  const char* spectrum;     /* NULL: any; else the stored spectrum family, e.g. "jonswap" */
  double speed_kt;          /* tow speed [kt], > 0 */
  double wind_kt;           /* wind speed [kt] of a Pierson-Moskowitz sea; NaN when hs_ft is used */
  double hs_ft;             /* significant wave height [ft] of a two-parameter sea; NaN for wind seas */
  double tp_s;              /* peak period [s] with hs_ft; NaN when the database has one period */
  double heading_deg;       /* wave heading [deg] in [0, 360]; 0 = following seas */
  double length_ft;         /* towline (hawser) length [ft], > 0 */
  double mean_tension_lbf;  /* mean towline tension [lbf] > 0; NaN: the calculated one (EQ-QUERY-9), or
                               each node's highest stored one where the database has no calculated values */
  double probability;       /* exceedance probability of the tow's maximum, in (0, 1); default 0.001 */
  double tow_days;          /* tow duration [days] >= 1; default 1 */
  int extrapolate;          /* 0: refuse outside the data (default); 1: extrapolate and warn */
  int on_brake;             /* 0: automatic towing machine, mean <= BS/3 (default); 1: brake, BS/5 */
} towdb_query_request;

/* The answer to one query. */
typedef struct towdb_query_result {
  double dynamic_tension_kips;     /* x(p, D), EQ-QUERY-3 */
  double dynamic_999_kips;         /* x(0.001, 1): the database's planning value */
  double mean_tension_lbf;         /* the mean tension used */
  double extreme_tension_lbf;      /* mean + dynamic, EQ-QUERY-4 */
  double breaking_strength_lbf;    /* towline breaking strength (smallest over the corner cases) */
  double extreme_limit_lbf;        /* BS / 1.5 */
  double mean_limit_lbf;           /* BS / 3 or BS / 5 */
  int extreme_check_passed;        /* extreme <= BS/1.5 */
  int mean_check_passed;           /* mean <= BS/3 (or BS/5 on the brake) */
  double gumbel_u_kips;            /* interpolated one-day location u */
  double gumbel_alpha_per_kip;     /* interpolated one-day alpha = 1/beta */
  double interpolation_error_kips; /* EQ-QUERY-7 estimate for x(p, D) */
  double ci_level;                 /* confidence level of the stored interval (e.g. 0.9) */
  double ci_low_kips;              /* interpolated stored interval of dynamic_999 */
  double ci_high_kips;
  double uncertainty_kips;         /* sqrt(interp^2 + scaled CI half-width^2), EQ-QUERY-7 */
  double slack_fraction;           /* interpolated fraction of time the line was slack */
  int interpolation_space;         /* TOWDB_QUERY_SPACE_LINEAR or _LOG */
  int extrapolated;                /* 1 when any axis was extrapolated */
  int warning_count;               /* warnings: towdb_query_warning(db, 0 .. count-1) */
  int nearest_count;               /* nearest stored cases: towdb_query_nearest(db, i, ...) */
  double calculated_mean_tension_lbf; /* EQ-QUERY-9 T_calc at the query; NaN when not stored */
  double mean_tension_factor;         /* EQ-QUERY-9 mean / T_calc; NaN when not stored */
  double catenary_sag_ft;             /* the static catenary's largest sag below the chord between the tow
                                         points [ft], interpolated as the tension (the line hangs this far
                                         below the straight line joining them: with the tow points' depths it
                                         says whether the line reaches the bottom); NaN when not stored */
  double equivalent_wind_kt;          /* EQ-QUERY-10: the wind of the fully developed sea with the asked
                                         hs_ft, when the database holds wind seas only; NaN otherwise */
  double catenary_depth_ft;           /* depth of the static catenary's lowest point below the still waterline
                                         [ft], interpolated as catenary_sag_ft (compare with the water depth:
                                         the line drags on the bottom where it is deeper); negative when the
                                         whole line hangs above the water; NaN when not stored (fits written
                                         before schema 6 and not yet refreshed by a build) */
} towdb_query_result;

/* One stored case near the query, with its own values. */
typedef struct towdb_query_case {
  long long case_id;
  double speed_kt, wind_kt, hs_ft, tp_s; /* NaN where the case has none */
  double heading_deg;                     /* as stored (not folded) */
  double length_ft, mean_tension_lbf;
  int days;                               /* simulated days */
  double dynamic_999_kips;                /* stored planning value */
  double dynamic_tension_kips;            /* this case's x(p, D) at the query's p and D */
  double distance;                        /* normalised distance to the query (grid-cell units) */
} towdb_query_case;

/* Result of an inverse query (maximum speed / minimum towline length). */
typedef struct towdb_query_search {
  int found;          /* 1: `value` passes both checks; 0: nothing in the range passes */
  double value;       /* max speed [kt] or min length [ft] that passes (NaN if none) */
  double range_low;   /* the searched range (the stored grid range) */
  double range_high;
  int evaluations;    /* interpolant evaluations used */
} towdb_query_search;

/* Leave-one-out statistics (EQ-QUERY-8) of relative errors of dynamic_999. */
typedef struct towdb_query_loo {
  int space;             /* the space tested */
  int axis;              /* TOWDB_QUERY_AXIS_* or TOWDB_QUERY_AXIS_ALL */
  int samples;           /* predictions made */
  double median_rel_error;
  double p90_rel_error;
  double max_rel_error;
  double median_abs_error_kips;
} towdb_query_loo;

TOWDB_QUERY_API const char* towdb_query_version(void);

/* Opens a towdb database read-only and loads its finished cases. `space` is
 * a TOWDB_QUERY_SPACE_* value. *out receives a handle even on failure (NULL
 * only when out of memory) so the message can be read; close it always. */
TOWDB_QUERY_API int towdb_query_open(const char* path, int space, towdb_query_db** out);
TOWDB_QUERY_API void towdb_query_close(towdb_query_db* db);

/* The message of the last failed call on `db` ("" after success). */
TOWDB_QUERY_API const char* towdb_query_errmsg(const towdb_query_db* db);
/* The code of the last call on `db`. */
TOWDB_QUERY_API int towdb_query_errcode(const towdb_query_db* db);

/* Counts of loaded data; the space chosen when opening (EQ-QUERY-6). */
TOWDB_QUERY_API int towdb_query_case_count(const towdb_query_db* db);
TOWDB_QUERY_API int towdb_query_space(const towdb_query_db* db);

TOWDB_QUERY_API void towdb_query_request_init(towdb_query_request* request);

TOWDB_QUERY_API int towdb_query_run(towdb_query_db* db, const towdb_query_request* request,
                                    towdb_query_result* result);
/* Warning `index` of the last successful run or search (NULL if out of range);
 * *kind (may be NULL) receives its TOWDB_QUERY_WARN_* kind. */
TOWDB_QUERY_API const char* towdb_query_warning(const towdb_query_db* db, int index, int* kind);
TOWDB_QUERY_API int towdb_query_nearest(const towdb_query_db* db, int index, towdb_query_case* out);
/* The database's names of the tug and tow that the last successful run (or
 * found search) matched, e.g. "YRBM" for a request's "yrbm"; owned by the
 * handle. TOWDB_QUERY_MISUSE when there is no such answer. */
TOWDB_QUERY_API int towdb_query_names(const towdb_query_db* db, const char** tug, const char** tow);

/* Highest speed in the stored speed range at which both checks of EQ-QUERY-5
 * pass and the mean tension is within the tugs' 125,000 lbf (thesis ch. 5;
 * with the calculated default mean tension, which rises with speed, that is
 * the tow's speed limit; TOWDB_QUERY_WARN_ABOVE_CAPACITY says when it bound)
 * (request->speed_kt ignored); `at_value` (may be NULL) receives the answer
 * there. Likewise the shortest towline length (request->length_ft ignored).
 * Extrapolation is never used by a search. */
TOWDB_QUERY_API int towdb_query_max_speed(towdb_query_db* db, const towdb_query_request* request,
                                          towdb_query_search* search, towdb_query_result* at_value);
TOWDB_QUERY_API int towdb_query_min_length(towdb_query_db* db, const towdb_query_request* request,
                                           towdb_query_search* search, towdb_query_result* at_value);

/* Leave-one-out error of the database in a given space (not AUTO) along one
 * axis or all (EQ-QUERY-8). */
TOWDB_QUERY_API int towdb_query_leave_one_out(towdb_query_db* db, int space, int axis, towdb_query_loo* out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TOWDB_QUERY_H */
