#define MODE 2
#define TOPIC                                                                                      \
    "robot/"                                                                                       \
    "scan"
#if MODE == 1 && defined(X)
    class A : public rclcpp::Node
{
#elif RCLCPP_VERSION_GTE(28, 0, 0) || (MODE * 3) / 0
    class A : public rclcpp::Node
{
#else
#endif
public:
    A() : Node("a")
    {
        /* #if 0 */ pub_ = create_publisher<std_msgs::msg::String>(TOPIC, 10);
        auto s = R"x(
#endif
)x";
    }
};
#endif
#endif
#ifdef
#if (((1
