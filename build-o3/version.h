#define GIT_COMMIT "bb60ccf8a2ca-dirty"
