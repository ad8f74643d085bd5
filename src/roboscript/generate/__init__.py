"""Generation: random worlds from recipes, scene descriptions, tasks an LLM suggests, template task families with
oracle programs, generated suites and verified (query, world, program) data sets (docs/generation.md)."""
