"""fgc and the outside world: GTSAM both ways (``to_gtsam``: an fgc Graph as GTSAM factors, the
numeric references and the checks ``fgc verify`` runs; ``from_gtsam``: a GTSAM graph as an fgc
Graph), the oracles for streaming, the data files of GTSAM's wheel, pose-graph file readers and
estimates out (JSON, g2o, TUM, CSV)."""
