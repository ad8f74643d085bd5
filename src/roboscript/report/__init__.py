"""Reports of benchmark runs and studies: plots (PNG) and one HTML page with the tables, plots and videos."""
