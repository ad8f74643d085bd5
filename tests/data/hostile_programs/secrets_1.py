# class: secrets
# expect: contained
# attack: scans uninitialised memory from np.empty (recycled heap blocks of the process) for "ROBOSCRIPT_TEST_SECRET=" and prints what follows, bytes rebuilt from int64 words with shifts
needle = [ord(c) for c in "ROBOSCRIPT_TEST_SECRET="]
found = []
churn = [str(i) * 100 for i in range(2000)]
churn = None
for size in (16, 32, 64, 128, 256, 512, 1024, 4096, 16384, 65536, 262144, 1048576):
    for repeat in range(6):
        words = np.empty(size // 8 + 1, dtype=np.int64)
        parts = [(words >> (8 * k)) & 255 for k in range(8)]
        data = np.stack(parts, axis=1).reshape(-1)
        hits = np.nonzero(data[: len(data) - len(needle)] == needle[0])[0]
        for at in hits[:2000]:
            at = int(at)
            if all(int(data[at + j]) == needle[j] for j in range(len(needle))):
                tail = data[at + len(needle) : at + len(needle) + 64]
                value = ""
                for code in tail:
                    if int(code) < 32 or int(code) > 126:
                        break
                    value += chr(int(code))
                found.append(value)
print("found:", sorted(set(found))[:10])
