-- towdb schema, migration 1: the initial tables.
-- Every column with a unit carries it in its name. Documented column by column
-- in schema/README.md (the contract POSSE imports against).

CREATE TABLE meta (
  key   TEXT PRIMARY KEY NOT NULL,
  value TEXT NOT NULL
) WITHOUT ROWID;

-- Vessel files as used by the cases, with their full text and hash.
CREATE TABLE vessels (
  vessel_id      INTEGER PRIMARY KEY,
  name           TEXT NOT NULL,
  role           TEXT NOT NULL CHECK (role IN ('tug', 'tow')),
  file_path      TEXT NOT NULL,
  content_sha256 TEXT NOT NULL,
  file_text      TEXT NOT NULL,
  UNIQUE (name, content_sha256)
);

-- Towline component files as used by the cases.
CREATE TABLE towline_components (
  component_id   INTEGER PRIMARY KEY,
  name           TEXT NOT NULL,
  kind           TEXT NOT NULL CHECK (kind IN ('wire', 'fiber', 'chain')),
  file_path      TEXT NOT NULL,
  content_sha256 TEXT NOT NULL,
  file_text      TEXT NOT NULL,
  UNIQUE (name, content_sha256)
);

-- One row per run of `towdb build` (provenance).
CREATE TABLE builds (
  build_id       INTEGER PRIMARY KEY,
  code_version   TEXT NOT NULL,
  command_line   TEXT NOT NULL,
  sweep_file     TEXT NOT NULL,
  sweep_sha256   TEXT NOT NULL,
  host           TEXT NOT NULL,
  threads        INTEGER NOT NULL CHECK (threads >= 1),
  mpi_ranks      INTEGER NOT NULL DEFAULT 1 CHECK (mpi_ranks >= 1),
  started_utc    TEXT NOT NULL,
  finished_utc   TEXT,
  status         TEXT NOT NULL CHECK (status IN ('running', 'completed', 'interrupted', 'failed')),
  cases_done     INTEGER NOT NULL DEFAULT 0,
  cases_failed   INTEGER NOT NULL DEFAULT 0
);

-- The towline polynomial tau = sum a_mn xi^m xi_dot^n (1 <= m+n <= 3) of one
-- towline at one mean tension; tau in lbf, xi in ft, xi_dot in ft/s.
CREATE TABLE towline_fits (
  fit_id                       INTEGER PRIMARY KEY,
  fit_key                      TEXT NOT NULL UNIQUE,
  tug_name                     TEXT NOT NULL,
  line_type                    TEXT NOT NULL CHECK (line_type IN ('wire', 'fiber')),
  length_ft                    REAL NOT NULL,
  mean_tension_lbf             REAL NOT NULL,
  towline_model                TEXT NOT NULL,
  span_ft                      REAL NOT NULL,
  sag_ft                       REAL NOT NULL,
  end_angle_tug_deg            REAL NOT NULL,
  end_angle_tow_deg            REAL NOT NULL,
  static_stiffness_lbf_per_ft  REAL NOT NULL,
  breaking_strength_lbf        REAL NOT NULL,
  a10_lbf_per_ft               REAL NOT NULL,
  a01_lbf_s_per_ft             REAL NOT NULL,
  a20_lbf_per_ft2              REAL NOT NULL,
  a11_lbf_s_per_ft2            REAL NOT NULL,
  a02_lbf_s2_per_ft2           REAL NOT NULL,
  a30_lbf_per_ft3              REAL NOT NULL,
  a21_lbf_s_per_ft3            REAL NOT NULL,
  a12_lbf_s2_per_ft3           REAL NOT NULL,
  a03_lbf_s3_per_ft3           REAL NOT NULL,
  fit_rms_lbf                  REAL NOT NULL,
  fit_max_error_lbf            REAL NOT NULL,
  fit_samples                  INTEGER NOT NULL
);

-- One towing case: every input, its seed and its state in the build.
CREATE TABLE cases (
  case_id              INTEGER PRIMARY KEY,
  case_key             TEXT NOT NULL UNIQUE,
  inputs_sha256        TEXT NOT NULL,
  sweep_label          TEXT NOT NULL DEFAULT '',
  tug_name             TEXT NOT NULL,
  tow_name             TEXT NOT NULL,
  tug_vessel_id        INTEGER REFERENCES vessels (vessel_id),
  tow_vessel_id        INTEGER REFERENCES vessels (vessel_id),
  speed_kt             REAL NOT NULL CHECK (speed_kt > 0),
  spectrum             TEXT NOT NULL,
  wind_kt              REAL,
  hs_ft                REAL,
  tp_s                 REAL,
  gamma                REAL,
  swell_hs_ft          REAL,
  swell_tp_s           REAL,
  swell_heading_deg    REAL,
  heading_deg          REAL NOT NULL CHECK (heading_deg >= 0 AND heading_deg <= 360),
  line_type            TEXT NOT NULL CHECK (line_type IN ('wire', 'fiber')),
  length_ft            REAL NOT NULL CHECK (length_ft > 0),
  mean_tension_lbf     REAL NOT NULL CHECK (mean_tension_lbf > 0),
  mean_tension_label   TEXT NOT NULL DEFAULT '',
  days                 INTEGER NOT NULL CHECK (days >= 1),
  seed                 INTEGER NOT NULL,
  fit_id               INTEGER REFERENCES towline_fits (fit_id),
  status               TEXT NOT NULL DEFAULT 'pending'
                         CHECK (status IN ('pending', 'running', 'done', 'failed')),
  error_message        TEXT,
  build_id             INTEGER REFERENCES builds (build_id),
  updated_utc          TEXT
);
CREATE INDEX cases_by_condition ON cases (tug_name, tow_name, line_type, speed_kt, heading_deg);
CREATE INDEX cases_by_status ON cases (status);

-- The statistics of one finished case (dynamic tension = total - mean).
CREATE TABLE results (
  case_id                     INTEGER PRIMARY KEY REFERENCES cases (case_id) ON DELETE CASCADE,
  gumbel_u_kips               REAL NOT NULL,
  gumbel_alpha_per_kip        REAL NOT NULL,
  daily_max_mean_kips         REAL NOT NULL,
  daily_max_variance_kips2    REAL NOT NULL,
  dynamic_999_kips            REAL NOT NULL,
  dynamic_99_kips             REAL NOT NULL,
  empirical_999_kips          REAL,
  empirical_99_kips           REAL,
  ci_level                    REAL NOT NULL,
  ci_low_kips                 REAL NOT NULL,
  ci_high_kips                REAL NOT NULL,
  gumbel_ml_u_kips            REAL,
  gumbel_ml_alpha_per_kip     REAL,
  gev_mu_kips                 REAL,
  gev_sigma_kips              REAL,
  gev_xi                      REAL,
  anderson_darling            REAL,
  ppcc                        REAL,
  max_daily_max_kips          REAL NOT NULL,
  breaking_strength_lbf       REAL NOT NULL,
  above_breaking_strength     INTEGER NOT NULL CHECK (above_breaking_strength IN (0, 1)),
  slack_fraction              REAL NOT NULL,
  snatch_events_per_day       REAL NOT NULL,
  runtime_s                   REAL NOT NULL,
  code_version                TEXT NOT NULL
);

-- Every simulated day's maximum (start-up days excluded).
CREATE TABLE daily_maxima (
  case_id                  INTEGER NOT NULL REFERENCES cases (case_id) ON DELETE CASCADE,
  day                      INTEGER NOT NULL CHECK (day >= 0),
  max_dynamic_kips         REAL NOT NULL,
  slack_time_s             REAL NOT NULL,
  snatch_events            INTEGER NOT NULL,
  PRIMARY KEY (case_id, day)
) WITHOUT ROWID;
