// A planted violation for gl_lifetime.planted_list_fails: a class forgetting its names by hand.
struct Planted {
  void abandon();
};
