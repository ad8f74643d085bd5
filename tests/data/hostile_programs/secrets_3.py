# class: secrets
# expect: contained
# attack: format walks from numpy's own functions (their __wrapped__ implementation's module globals reach warnings.sys and os) to the environment and the command line
u = "_" * 2
walks = [
    "{0." + u + "wrapped" + u + "." + u + "globals" + u + "[warnings].sys.modules[os].environ[ROBOSCRIPT_TEST_SECRET]}",
    "{0." + u + "wrapped" + u + "." + u + "wrapped" + u + "." + u + "globals" + u + "[warnings].sys.modules[os].environ[ROBOSCRIPT_TEST_SECRET]}",
    "{0." + u + "globals" + u + "[np].linalg.norm." + u + "wrapped" + u + "." + u + "globals" + u + "[warnings].sys.orig_argv}",
    "{0." + u + "wrapped" + u + "." + u + "globals" + u + "[warnings].sys.argv}",
]
for root in (np.linalg.norm, np.linspace, np.mean):
    for walk in walks:
        try:
            print(walk.format(root))
        except Exception as exc:
            print("refused:", str(exc)[:60])
